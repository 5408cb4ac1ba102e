/* sl_mesh: procedural meshes (plane, box, sphere, cylinder, torus) with normals,
 * and their upload to GL vertex arrays.
 *
 * Vertex layout: 6 floats per vertex, position xyz then unit normal xyz.
 * Attribute locations: 0 = position, 1 = normal (see SL_ATTRIB_*).
 * All shapes are centred on the origin; the plane lies in y = 0 facing +y;
 * the cylinder's axis is y. Triangles wind counter-clockwise seen from outside. */
#ifndef SL_MESH_H
#define SL_MESH_H

#include <stdbool.h>
#include <stdint.h>

#include "sl_gl.h"
#include "sl_scene.h"

enum { SL_ATTRIB_POSITION = 0, SL_ATTRIB_NORMAL = 1 };

typedef struct sl_mesh_data {
    float *vertices;      /* vertex_count * 6 floats */
    uint32_t *indices;    /* index_count indices, triangles */
    int vertex_count;
    int index_count;
} sl_mesh_data;

/* Each returns a mesh whose arrays the caller frees with sl_mesh_data_free.
 * On allocation failure the arrays are NULL and the counts 0. */
sl_mesh_data sl_mesh_plane(float size_x, float size_z, int subdivisions);
sl_mesh_data sl_mesh_box(float size_x, float size_y, float size_z);
sl_mesh_data sl_mesh_sphere(float radius, int slices, int stacks);
sl_mesh_data sl_mesh_cylinder(float radius, float height, int slices); /* capped */
sl_mesh_data sl_mesh_torus(float major_radius, float minor_radius, int rings, int sides); /* ring in the xz plane */
void sl_mesh_data_free(sl_mesh_data *data);
/* The mesh of a scene object's shape and size, in its own space (the model
 * matrix places it); the same tessellation wherever it is drawn. */
sl_mesh_data sl_mesh_for_object(const sl_object *object);

/* Object-space bounds of the vertices. */
void sl_mesh_data_bounds(const sl_mesh_data *data, float min[3], float max[3]);

typedef struct sl_mesh {
    GLuint vao, vbo, ebo;
    int index_count;
} sl_mesh;

/* Needs a current GL context. Returns false if data is empty. */
bool sl_mesh_upload(sl_mesh *mesh, const sl_mesh_data *data);
void sl_mesh_draw(const sl_mesh *mesh);
void sl_mesh_destroy(sl_mesh *mesh);

#endif
