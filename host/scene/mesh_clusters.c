#include "mesh_clusters.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    uint32_t code;     /* Z-order (Morton) code of the centroid, 10 bits per axis */
    uint32_t triangle; /* original index: ties keep the file's order */
} triangle_key;

static double coordinate(const tarn_vec3 *p, int axis)
{
    tarn_q16 v = axis == 0 ? p->x : (axis == 1 ? p->y : p->z);
    return v / 65536.0;
}

/* Spreads the low 10 bits of v to every third bit. */
static uint32_t spread_bits(uint32_t v)
{
    v &= 0x3FFu;
    v = (v | (v << 16)) & 0x030000FFu;
    v = (v | (v << 8)) & 0x0300F00Fu;
    v = (v | (v << 4)) & 0x030C30C3u;
    v = (v | (v << 2)) & 0x09249249u;
    return v;
}

static int compare_keys(const void *a, const void *b)
{
    const triangle_key *x = a, *y = b;
    if (x->code != y->code) return x->code < y->code ? -1 : 1;
    return x->triangle < y->triangle ? -1 : (x->triangle > y->triangle);
}

static void mesh_bounds(const tarn_mesh *mesh, double low[3], double high[3])
{
    for (int a = 0; a < 3; a++) low[a] = high[a] = coordinate(&mesh->positions[0], a);
    for (uint32_t v = 1; v < mesh->vertex_count; v++)
        for (int a = 0; a < 3; a++) {
            double c = coordinate(&mesh->positions[v], a);
            low[a] = fmin(low[a], c);
            high[a] = fmax(high[a], c);
        }
}

static void sort_keys(const tarn_mesh *mesh, triangle_key *keys)
{
    double low[3], high[3];
    mesh_bounds(mesh, low, high);
    for (uint32_t t = 0; t < mesh->triangle_count; t++) {
        uint32_t code = 0;
        for (int a = 0; a < 3; a++) {
            double centroid = 0;
            for (int k = 0; k < 3; k++) centroid += coordinate(&mesh->positions[mesh->indices[3 * t + k]], a) / 3;
            double extent = high[a] - low[a];
            uint32_t cell = extent > 0 ? (uint32_t)fmin(1023, (centroid - low[a]) / extent * 1024) : 0;
            code |= spread_bits(cell) << a;
        }
        keys[t].code = code;
        keys[t].triangle = t;
    }
    qsort(keys, mesh->triangle_count, sizeof *keys, compare_keys);
}

/* The sphere around the bounding box's centre that holds every vertex of the run,
 * rounded outward to Q16.16. */
static tarn_cluster bound_run(const tarn_mesh *mesh, uint32_t first, uint32_t count)
{
    double low[3], high[3], centre[3], radius = 0;
    const uint16_t *index = &mesh->indices[3 * first];
    for (int a = 0; a < 3; a++) low[a] = high[a] = coordinate(&mesh->positions[index[0]], a);
    for (uint32_t k = 1; k < 3 * count; k++)
        for (int a = 0; a < 3; a++) {
            double c = coordinate(&mesh->positions[index[k]], a);
            low[a] = fmin(low[a], c);
            high[a] = fmax(high[a], c);
        }
    tarn_cluster cluster;
    for (int a = 0; a < 3; a++) centre[a] = tarn_q16_from_double((low[a] + high[a]) / 2) / 65536.0;
    cluster.centre.x = tarn_q16_from_double(centre[0]);
    cluster.centre.y = tarn_q16_from_double(centre[1]);
    cluster.centre.z = tarn_q16_from_double(centre[2]);
    for (uint32_t k = 0; k < 3 * count; k++) {
        double d2 = 0;
        for (int a = 0; a < 3; a++) {
            double d = coordinate(&mesh->positions[index[k]], a) - centre[a];
            d2 += d * d;
        }
        radius = fmax(radius, sqrt(d2));
    }
    cluster.radius = (tarn_q16)fmin(ceil(radius * 65536.0) + 1, INT32_MAX);
    cluster.first_triangle = (uint16_t)first;
    cluster.triangle_count = (uint16_t)count;
    return cluster;
}

int tarn_mesh_build_clusters(tarn_mesh_buffer *m, tarn_error *err)
{
    const uint32_t triangles = m->mesh.triangle_count;
    if (triangles == 0) return 0;
    const uint32_t runs = (triangles + TARN_CLUSTER_TRIANGLES - 1) / TARN_CLUSTER_TRIANGLES;
    triangle_key *keys = malloc(triangles * sizeof *keys);
    uint16_t *ordered = malloc(3u * triangles * sizeof *ordered);
    tarn_cluster *clusters = malloc(runs * sizeof *clusters);
    if (keys == NULL || ordered == NULL || clusters == NULL) {
        free(keys);
        free(ordered);
        free(clusters);
        return tarn_fail(err, "out of memory ordering a mesh of %u triangles", (unsigned)triangles);
    }
    sort_keys(&m->mesh, keys);
    for (uint32_t t = 0; t < triangles; t++)
        memcpy(&ordered[3 * t], &m->indices[3 * keys[t].triangle], 3 * sizeof *ordered);
    memcpy(m->indices, ordered, 3u * triangles * sizeof *ordered);
    for (uint32_t r = 0; r < runs; r++) {
        uint32_t first = r * TARN_CLUSTER_TRIANGLES;
        uint32_t count = triangles - first < TARN_CLUSTER_TRIANGLES ? triangles - first : TARN_CLUSTER_TRIANGLES;
        clusters[r] = bound_run(&m->mesh, first, count);
    }
    free(keys);
    free(ordered);
    free(m->clusters);
    m->clusters = clusters;
    m->mesh.clusters = clusters;
    m->mesh.cluster_count = (uint16_t)runs;
    return 0;
}
