/* sl_mesh: procedural meshes and their upload to GL vertex arrays. */
#include "sl_mesh.h"

#include <limits.h>
#include <math.h>
#include <stdlib.h>

static const double _sl_pi = 3.14159265358979323846;

/* Fills a mesh in order; the counts are known up front, so one allocation each. */
typedef struct _sl_builder {
    sl_mesh_data data;
} _sl_builder;

static sl_mesh_data _sl_mesh_empty(void) {
    sl_mesh_data empty = {NULL, NULL, 0, 0};
    return empty;
}

/* Sizes come in as size_t so that large parameters are caught instead of
 * overflowing int arithmetic. */
static bool _sl_builder_init(_sl_builder *b, size_t vertex_count, size_t index_count) {
    b->data = _sl_mesh_empty();
    /* Indices are uint32_t and counts are int: stay below INT_MAX for both. */
    if (vertex_count == 0 || index_count == 0 || vertex_count > (size_t)INT_MAX / 6 ||
        index_count > (size_t)INT_MAX)
        return false;
    b->data.vertices = malloc(vertex_count * 6 * sizeof(float));
    b->data.indices = malloc(index_count * sizeof(uint32_t));
    if (!b->data.vertices || !b->data.indices) {
        free(b->data.vertices);
        free(b->data.indices);
        b->data = _sl_mesh_empty();
        return false;
    }
    return true;
}

static uint32_t _sl_builder_vertex(_sl_builder *b, float px, float py, float pz, float nx, float ny,
                                   float nz) {
    float *v = b->data.vertices + (size_t)b->data.vertex_count * 6;
    v[0] = px;
    v[1] = py;
    v[2] = pz;
    v[3] = nx;
    v[4] = ny;
    v[5] = nz;
    return (uint32_t)b->data.vertex_count++;
}

static void _sl_builder_triangle(_sl_builder *b, uint32_t i0, uint32_t i1, uint32_t i2) {
    uint32_t *t = b->data.indices + b->data.index_count;
    t[0] = i0;
    t[1] = i1;
    t[2] = i2;
    b->data.index_count += 3;
}

/* Two triangles for a quad whose corners a, b, c, d run counter-clockwise. */
static void _sl_builder_quad(_sl_builder *b, uint32_t a, uint32_t bb, uint32_t c, uint32_t d) {
    _sl_builder_triangle(b, a, bb, c);
    _sl_builder_triangle(b, a, c, d);
}

sl_mesh_data sl_mesh_plane(float size_x, float size_z, int subdivisions) {
    int n = subdivisions < 1 ? 1 : subdivisions;
    size_t row = (size_t)n + 1;
    _sl_builder b;
    if (n > 46000 || !_sl_builder_init(&b, row * row, (size_t)n * (size_t)n * 6))
        return _sl_mesh_empty();

    /* Vertex (i, j) sits at column i along x and row j along z. */
    for (int j = 0; j <= n; j++) {
        float z = size_z * ((float)j / (float)n - 0.5f);
        for (int i = 0; i <= n; i++) {
            float x = size_x * ((float)i / (float)n - 0.5f);
            _sl_builder_vertex(&b, x, 0.0f, z, 0.0f, 1.0f, 0.0f);
        }
    }
    for (int j = 0; j < n; j++) {
        for (int i = 0; i < n; i++) {
            uint32_t a = (uint32_t)((size_t)j * row + (size_t)i);
            uint32_t next_row = a + (uint32_t)row;
            /* Seen from +y, +z points towards the viewer's bottom, so
             * (i,j) -> (i,j+1) -> (i+1,j+1) is counter-clockwise. */
            _sl_builder_quad(&b, a, next_row, next_row + 1, a + 1);
        }
    }
    return b.data;
}

sl_mesh_data sl_mesh_box(float size_x, float size_y, float size_z) {
    /* Per face: outward normal n and in-plane axis u; v = n x u, so the corners
     * -u-v, +u-v, +u+v, -u+v run counter-clockwise seen along -n. */
    static const float faces[6][2][3] = {
        {{1, 0, 0}, {0, 0, -1}}, {{-1, 0, 0}, {0, 0, 1}}, {{0, 1, 0}, {1, 0, 0}},
        {{0, -1, 0}, {1, 0, 0}}, {{0, 0, 1}, {1, 0, 0}},  {{0, 0, -1}, {-1, 0, 0}},
    };
    static const float corners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    const float half[3] = {0.5f * size_x, 0.5f * size_y, 0.5f * size_z};
    _sl_builder b;
    if (!_sl_builder_init(&b, 24, 36))
        return _sl_mesh_empty();

    for (int f = 0; f < 6; f++) {
        const float *n = faces[f][0];
        const float *u = faces[f][1];
        const float v[3] = {n[1] * u[2] - n[2] * u[1], n[2] * u[0] - n[0] * u[2],
                            n[0] * u[1] - n[1] * u[0]};
        uint32_t first = 0;
        for (int c = 0; c < 4; c++) {
            float p[3];
            for (int k = 0; k < 3; k++)
                p[k] = (n[k] + corners[c][0] * u[k] + corners[c][1] * v[k]) * half[k];
            uint32_t index = _sl_builder_vertex(&b, p[0], p[1], p[2], n[0], n[1], n[2]);
            if (c == 0)
                first = index;
        }
        _sl_builder_quad(&b, first, first + 1, first + 2, first + 3);
    }
    return b.data;
}

sl_mesh_data sl_mesh_sphere(float radius, int slices, int stacks) {
    int ns = slices < 3 ? 3 : slices;
    int nt = stacks < 2 ? 2 : stacks;
    size_t row = (size_t)ns + 1; /* seam column duplicated, as for texture coordinates */
    _sl_builder b;
    /* Two triangles per quad, less one per quad in the rows touching a pole. */
    if (ns > 46000 || nt > 46000 ||
        !_sl_builder_init(&b, row * ((size_t)nt + 1), (size_t)ns * ((size_t)nt - 1) * 6))
        return _sl_mesh_empty();

    /* phi runs from the north pole down; theta turns from +z towards +x. */
    for (int i = 0; i <= nt; i++) {
        double phi = _sl_pi * (double)i / (double)nt;
        float sp = (float)sin(phi), cp = (float)cos(phi);
        if (i == 0 || i == nt)
            sp = 0.0f; /* exact poles, so normals there are exactly +-y */
        for (int j = 0; j <= ns; j++) {
            double theta = 2.0 * _sl_pi * (double)j / (double)ns;
            float nx = sp * (float)sin(theta), ny = cp, nz = sp * (float)cos(theta);
            _sl_builder_vertex(&b, radius * nx, radius * ny, radius * nz, nx, ny, nz);
        }
    }
    for (int i = 0; i < nt; i++) {
        for (int j = 0; j < ns; j++) {
            uint32_t a = (uint32_t)((size_t)i * row + (size_t)j); /* upper left, seen from outside */
            uint32_t below = a + (uint32_t)row;
            /* At a pole one triangle of the quad has zero area: leave it out. */
            if (i != 0)
                _sl_builder_triangle(&b, a, below, a + 1);
            if (i != nt - 1)
                _sl_builder_triangle(&b, a + 1, below, below + 1);
        }
    }
    return b.data;
}

sl_mesh_data sl_mesh_cylinder(float radius, float height, int slices) {
    int ns = slices < 3 ? 3 : slices;
    size_t ring = (size_t)ns + 1;
    float top = 0.5f * height, bottom = -0.5f * height;
    _sl_builder b;
    /* Side: two rings. Caps: a centre and a ring each, with their own normals. */
    if (ns > 1000000 || !_sl_builder_init(&b, 4 * ring + 2, (size_t)ns * 12))
        return _sl_mesh_empty();

    uint32_t side = (uint32_t)b.data.vertex_count;
    for (int j = 0; j <= ns; j++) {
        double theta = 2.0 * _sl_pi * (double)j / (double)ns;
        float nx = (float)sin(theta), nz = (float)cos(theta);
        _sl_builder_vertex(&b, radius * nx, top, radius * nz, nx, 0.0f, nz);
        _sl_builder_vertex(&b, radius * nx, bottom, radius * nz, nx, 0.0f, nz);
    }
    for (int j = 0; j < ns; j++) {
        uint32_t t0 = side + 2 * (uint32_t)j, b0 = t0 + 1, t1 = t0 + 2, b1 = t0 + 3;
        _sl_builder_quad(&b, t0, b0, b1, t1);
    }

    for (int cap = 0; cap < 2; cap++) {
        float y = cap == 0 ? top : bottom;
        float ny = cap == 0 ? 1.0f : -1.0f;
        uint32_t centre = _sl_builder_vertex(&b, 0.0f, y, 0.0f, 0.0f, ny, 0.0f);
        for (int j = 0; j <= ns; j++) {
            double theta = 2.0 * _sl_pi * (double)j / (double)ns;
            _sl_builder_vertex(&b, radius * (float)sin(theta), y, radius * (float)cos(theta), 0.0f,
                               ny, 0.0f);
        }
        for (int j = 0; j < ns; j++) {
            uint32_t r0 = centre + 1 + (uint32_t)j;
            /* theta turns counter-clockwise seen from +y, clockwise from -y. */
            if (cap == 0)
                _sl_builder_triangle(&b, centre, r0, r0 + 1);
            else
                _sl_builder_triangle(&b, centre, r0 + 1, r0);
        }
    }
    return b.data;
}

sl_mesh_data sl_mesh_torus(float major_radius, float minor_radius, int rings, int sides) {
    int nr = rings < 3 ? 3 : rings;
    int ns = sides < 3 ? 3 : sides;
    size_t row = (size_t)ns + 1;
    _sl_builder b;
    if (nr > 46000 || ns > 46000 ||
        !_sl_builder_init(&b, ((size_t)nr + 1) * row, (size_t)nr * (size_t)ns * 6))
        return _sl_mesh_empty();

    /* u goes round the ring (from +z towards +x), v round the tube (from the
     * outside towards +y); vertex (i, j) is at u_i, v_j. */
    for (int i = 0; i <= nr; i++) {
        double u = 2.0 * _sl_pi * (double)i / (double)nr;
        float su = (float)sin(u), cu = (float)cos(u);
        for (int j = 0; j <= ns; j++) {
            double v = 2.0 * _sl_pi * (double)j / (double)ns;
            float sv = (float)sin(v), cv = (float)cos(v);
            float nx = cv * su, ny = sv, nz = cv * cu;
            _sl_builder_vertex(&b, major_radius * su + minor_radius * nx, minor_radius * ny,
                               major_radius * cu + minor_radius * nz, nx, ny, nz);
        }
    }
    for (int i = 0; i < nr; i++) {
        for (int j = 0; j < ns; j++) {
            uint32_t a = (uint32_t)((size_t)i * row + (size_t)j);
            uint32_t next = a + (uint32_t)row;
            /* On the outside u increases rightwards and v upwards. */
            _sl_builder_quad(&b, a, next, next + 1, a + 1);
        }
    }
    return b.data;
}

void sl_mesh_data_free(sl_mesh_data *data) {
    if (!data)
        return;
    free(data->vertices);
    free(data->indices);
    *data = _sl_mesh_empty();
}

void sl_mesh_data_bounds(const sl_mesh_data *data, float min[3], float max[3]) {
    if (!data || !data->vertices || data->vertex_count <= 0) {
        for (int k = 0; k < 3; k++)
            min[k] = max[k] = 0.0f;
        return;
    }
    for (int k = 0; k < 3; k++)
        min[k] = max[k] = data->vertices[k];
    for (int i = 1; i < data->vertex_count; i++) {
        const float *p = data->vertices + (size_t)i * 6;
        for (int k = 0; k < 3; k++) {
            if (p[k] < min[k])
                min[k] = p[k];
            if (p[k] > max[k])
                max[k] = p[k];
        }
    }
}

bool sl_mesh_upload(sl_mesh *mesh, const sl_mesh_data *data) {
    mesh->vao = mesh->vbo = mesh->ebo = 0;
    mesh->index_count = 0;
    if (!data || !data->vertices || !data->indices || data->vertex_count <= 0 ||
        data->index_count <= 0)
        return false;

    const GLsizei stride = (GLsizei)(6 * sizeof(float));
    glGenVertexArrays(1, &mesh->vao);
    glBindVertexArray(mesh->vao);

    glGenBuffers(1, &mesh->vbo);
    glBindBuffer(GL_ARRAY_BUFFER, mesh->vbo);
    glBufferData(GL_ARRAY_BUFFER, (GLsizeiptr)((size_t)data->vertex_count * 6 * sizeof(float)),
                 data->vertices, GL_STATIC_DRAW);

    /* The element buffer binding is VAO state, so bind it while the VAO is bound. */
    glGenBuffers(1, &mesh->ebo);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, mesh->ebo);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER,
                 (GLsizeiptr)((size_t)data->index_count * sizeof(uint32_t)), data->indices,
                 GL_STATIC_DRAW);

    glEnableVertexAttribArray(SL_ATTRIB_POSITION);
    glVertexAttribPointer(SL_ATTRIB_POSITION, 3, GL_FLOAT, GL_FALSE, stride, (const void *)0);
    glEnableVertexAttribArray(SL_ATTRIB_NORMAL);
    glVertexAttribPointer(SL_ATTRIB_NORMAL, 3, GL_FLOAT, GL_FALSE, stride,
                          (const void *)(3 * sizeof(float)));

    /* Unbind the VAO first: unbinding the element buffer inside it would detach it. */
    glBindVertexArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);

    mesh->index_count = data->index_count;
    return true;
}

void sl_mesh_draw(const sl_mesh *mesh) {
    if (!mesh || mesh->vao == 0 || mesh->index_count <= 0)
        return;
    glBindVertexArray(mesh->vao);
    glDrawElements(GL_TRIANGLES, mesh->index_count, GL_UNSIGNED_INT, (const void *)0);
    glBindVertexArray(0);
}

void sl_mesh_destroy(sl_mesh *mesh) {
    if (!mesh)
        return;
    if (mesh->ebo)
        glDeleteBuffers(1, &mesh->ebo);
    if (mesh->vbo)
        glDeleteBuffers(1, &mesh->vbo);
    if (mesh->vao)
        glDeleteVertexArrays(1, &mesh->vao);
    mesh->vao = mesh->vbo = mesh->ebo = 0;
    mesh->index_count = 0;
}

sl_mesh_data sl_mesh_for_object(const sl_object *o) {
    switch (o->shape) {
    case SL_SHAPE_PLANE: return sl_mesh_plane(o->size[0], o->size[1], o->subdivisions);
    case SL_SHAPE_BOX: return sl_mesh_box(o->size[0], o->size[1], o->size[2]);
    case SL_SHAPE_SPHERE: return sl_mesh_sphere(o->size[0], 48, 24);
    case SL_SHAPE_CYLINDER: return sl_mesh_cylinder(o->size[0], o->size[1], 48);
    case SL_SHAPE_TORUS: return sl_mesh_torus(o->size[0], o->size[1], 48, 24);
    }
    return (sl_mesh_data){0};
}
