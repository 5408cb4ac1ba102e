#version 330 core
// Debug view of lab 7's cube map: the six faces unfolded as a cross, as seen
// from the light (a net folded around it), grey = stored distance / far.
//            [+Y]
//      [-X]  [-Z]  [+X]  [+Z]
//            [-Y]
in vec2 v_uv; // 0..1 over a 4:3 viewport
uniform samplerCube u_cube_map;
out vec4 frag_color;

void main() {
    vec2 g = v_uv * vec2(4.0, 3.0);
    ivec2 cell = ivec2(floor(g));
    vec2 st = fract(g) * 2.0 - 1.0;
    vec3 centre, right, up;
    if (cell.y == 1) {
        // looking around the horizon, up = +Y; each cell's right is the next cell's centre
        if (cell.x == 0) { centre = vec3(-1, 0, 0); right = vec3(0, 0, -1); }
        else if (cell.x == 1) { centre = vec3(0, 0, -1); right = vec3(1, 0, 0); }
        else if (cell.x == 2) { centre = vec3(1, 0, 0); right = vec3(0, 0, 1); }
        else { centre = vec3(0, 0, 1); right = vec3(-1, 0, 0); }
        up = vec3(0, 1, 0);
    } else if (cell.x == 1) {
        // above and below the -Z cell
        right = vec3(1, 0, 0);
        if (cell.y == 2) { centre = vec3(0, 1, 0); up = vec3(0, 0, 1); }
        else { centre = vec3(0, -1, 0); up = vec3(0, 0, -1); }
    } else {
        discard;
    }
    vec2 edge = abs(st);
    if (max(edge.x, edge.y) > 0.985) {
        frag_color = vec4(0.9, 0.5, 0.1, 1.0); // face outline
        return;
    }
    float d = texture(u_cube_map, centre + st.x * right + st.y * up).r;
    frag_color = vec4(vec3(sqrt(clamp(d, 0.0, 1.0))), 1.0);
}
