/* reference.c: the float reference renderer (see reference.h).
 *
 * Written from the pixel rules in core/include/tarn/tarn_render.h, in doubles, on purpose with
 * none of the core's arithmetic: a bug shared by both would be invisible. */
#include "reference.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "ref_geometry.h"
#include "ref_motion.h"
#include "ref_texel.h"
#include "reference_water.h"
#include "tarn/tarn_render.h"

#define Q16_SCALE 65536.0
#define INV_DEPTH_SCALE 1073741824.0 /* Q1.30 */
#define Q8_8_SCALE 256.0
#define FRESNEL_SCALE 32768.0 /* Q1.15 */

/* The continuous geometry clips every triangle to a frustum this many pixels wider
 * than the frame on each side: what lies beyond is never drawn, and what remains
 * projects within 2^17 pixels, 2^25 units of the finest grid, so no vertex of a
 * huge triangle seen through a tiny near plane lands where doubles lose the
 * differences between points (the core's triangles are held by its guard band). */
#define GUARD_BAND_PIXELS 65536.0
/* Below 2^26 every edge-function product fits the 53-bit mantissa: plain double
 * arithmetic is exact and the slower accurate form is not needed. */
#define EXACT_PRODUCT_LIMIT 67108864.0 /* 2^26 */

/* A vertex as the rasterizer sees it: everything interpolated across a triangle. */
typedef struct {
    double x, y;      /* screen position, subpixel units (integer-valued but in the
                         continuous geometry) */
    double inv_depth; /* near/d: linear in screen space, the perspective weight */
    double lit[3];    /* lit colour per channel, 0..255 */
    double uv[2];     /* texture coordinates, 1.0 = one texture width / height */
    double fresnel;   /* (1 - saturate(n.v))^2, water only */
} ref_screen_vertex;

/* A vertex in view space (x right, y up, z = depth d forward), before projection.
 * Every field is linear along an edge in view space, which is how clipping cuts. */
typedef struct {
    double view[3];
    double lit[3];
    double uv[2];
    double fresnel;
} ref_view_vertex;

typedef struct {
    int width, height;
    double subpixel_unit; /* 2^subpixel_bits: subpixel units per pixel */
    int continuous;       /* positions off the grid: no edge value is exact in doubles */
    uint8_t *rgb;
    uint32_t *surface; /* 0, or 1 + the object's index: what each pixel shows */
    const tarn_object *objects; /* the scene's, to name a pixel's surface */
    double *depth;    /* near/d per pixel in Q1.30 units, rounded; 0 = nothing drawn */
    double *inv_depth; /* near/d per pixel as interpolated, unrounded; 0 = nothing drawn */
    double near, far;  /* the camera's, world units */
    tarn_ref_camera camera;
    int plane_coordinates; /* flat water's coordinates from its plane: continuous, or
                              the core's quality takes them so (tarn_water_coordinates) */
    const tarn_ref_water_view *water; /* the opaque buffers, during the water pass */
} ref_target;

/* ---- scene validation: the reference must not read outside the scene's arrays --- */

static int mesh_is_valid(const tarn_mesh *mesh, int needs_normals)
{
    if (mesh->triangle_count == 0) return 1;
    if (mesh->indices == NULL || mesh->positions == NULL) return 0;
    if (needs_normals && mesh->normals == NULL) return 0;
    for (unsigned i = 0; i < 3u * mesh->triangle_count; i++)
        if (mesh->indices[i] >= mesh->vertex_count) return 0;
    return 1;
}

static int camera_is_valid(const tarn_camera *cam)
{
    int same_point = cam->position.x == cam->target.x && cam->position.y == cam->target.y
                     && cam->position.z == cam->target.z;
    return !same_point && cam->near > 0 && cam->far > cam->near
           && cam->fov_y_degrees >= TARN_Q16_ONE && cam->fov_y_degrees <= 179 * TARN_Q16_ONE;
}

static int scene_is_valid(const tarn_scene *scene)
{
    if (scene == NULL || !camera_is_valid(&scene->camera)) return 0;
    if (scene->object_count > 0 && scene->objects == NULL) return 0;
    for (unsigned i = 0; i < scene->object_count; i++) {
        const tarn_object *obj = &scene->objects[i];
        if (obj->mesh == NULL || obj->material == NULL) return 0;
        const tarn_material *mat = obj->material;
        if (!tarn_ref_texture_is_valid(mat->texture)) return 0;
        if (mat->water != NULL && !tarn_ref_water_is_valid(mat->water)) return 0;
        int fresnel = mat->water != NULL && (mat->water->features & TARN_WATER_FRESNEL);
        if (!mesh_is_valid(obj->mesh, !mat->unlit || fresnel)) return 0;
    }
    return scene->underwater == NULL || tarn_ref_underwater_is_valid(scene->underwater);
}

/* ---- exact edge tests ------------------------------------------------------------ */

/* a*b - c*d by Kahan's algorithm with fma: its relative error is at most 2 units in
 * the last place (Jeannerod, Louvet & Muller, 2013), so its sign is exact and it is
 * zero only when the true value is, whatever the magnitudes (short of overflow). */
static double accurate_product_difference(double a, double b, double c, double d)
{
    double cd = c * d;
    double cd_error = fma(-c, d, cd); /* cd - c*d, exactly */
    return fma(a, b, -cd) + cd_error;
}

/* One edge from `a` to `b` of a triangle wound so that its interior is where the
 * edge function is positive. */
typedef struct {
    double ax, ay, dx, dy;
    int owns_boundary; /* a top or left edge: centres exactly on it are inside */
} ref_edge;

/* Edge function of `e` at (px, py): twice the signed area of (a, b, p). With
 * `exact_in_double` every product fits the mantissa and plain arithmetic is exact;
 * otherwise the slower accurate form keeps the sign right. */
static double edge_value(const ref_edge *e, double px, double py, int exact_in_double)
{
    if (exact_in_double) return e->dx * (py - e->ay) - e->dy * (px - e->ax);
    return accurate_product_difference(e->dx, py - e->ay, e->dy, px - e->ax);
}

/* With positive-area winding in y-down screen coordinates the interior lies on the
 * side where y grows for an edge running in +x (so a horizontal edge with dx > 0 has
 * the triangle below it: a top edge) and on the side where x grows for an edge
 * running in -y (triangle to its right: a left edge). */
static ref_edge make_edge(const ref_screen_vertex *a, const ref_screen_vertex *b)
{
    ref_edge e = { a->x, a->y, b->x - a->x, b->y - a->y, 0 };
    e.owns_boundary = e.dy < 0 || (e.dy == 0 && e.dx > 0);
    return e;
}

/* ---- shading ---------------------------------------------------------------------- */

/* A covered pixel's attributes. */
typedef struct {
    double inv_depth; /* near/d, linear in screen space */
    double lit[3], uv[2], fresnel; /* perspective-correct */
} ref_pixel;

static double weighted(const double weight[3], double total, double a, double b, double c)
{
    return (weight[0] * a + weight[1] * b + weight[2] * c) / total;
}

/* `edge` / `area` are the pixel's screen-space barycentrics; weighted by each
 * vertex's inverse depth and renormalised they interpolate perspective-correctly. */
static ref_pixel interpolate(const ref_screen_vertex v[3], const double edge[3], double area)
{
    double weight[3];
    for (int k = 0; k < 3; k++) weight[k] = edge[k] / area * v[k].inv_depth;
    double total = weight[0] + weight[1] + weight[2];
    ref_pixel px;
    px.inv_depth = total;
    for (int k = 0; k < 2; k++)
        px.uv[k] = weighted(weight, total, v[0].uv[k], v[1].uv[k], v[2].uv[k]);
    for (int c = 0; c < 3; c++)
        px.lit[c] = weighted(weight, total, v[0].lit[c], v[1].lit[c], v[2].lit[c]);
    px.fresnel = weighted(weight, total, v[0].fresnel, v[1].fresnel, v[2].fresnel);
    return px;
}

static void shade_opaque(const ref_pixel *px, const tarn_texture *tex, uint8_t out[3])
{
    const uint8_t *texel = tex != NULL ? tarn_ref_sample_texel(tex, px->uv) : NULL;
    for (int c = 0; c < 3; c++) {
        double colour = texel != NULL ? texel[c] * px->lit[c] / 255.0 : px->lit[c];
        out[c] = (uint8_t)tarn_ref_round_to_byte(colour);
    }
}

/* Water reads the opaque pass's buffers, never its own output. Its depth is exact
 * near / (near/d), not the rounded Q1.30 the depth test uses. Flat water (a mesh
 * with a plane) takes its texture coordinates where the ray through the pixel's
 * centre meets its plane, where the core does (TARN_WATER_UV_PLANE): the same as
 * the continuous triangles interpolate, where snapped ones would move them. */
static void shade_water(const ref_target *t, const tarn_object *obj, int i, int j,
                        const ref_pixel *px, uint8_t out[3])
{
    tarn_ref_water_surface surface = {
        .depth = t->near / px->inv_depth,
        .lit = { px->lit[0], px->lit[1], px->lit[2] },
        .uv = { px->uv[0], px->uv[1] },
        .fresnel = px->fresnel,
    };
    if (t->plane_coordinates && obj->mesh->plane != NULL)
        (void)tarn_ref_plane_uv(&t->camera, obj, i + 0.5, j + 0.5, t->width, t->height, surface.uv);
    tarn_ref_shade_water(t->water, obj, i, j, &surface, out);
}

/* ---- rasterization ---------------------------------------------------------------- */

/* Range of pixel indices whose centres (i + 0.5) * unit lie in [lo, hi] (subpixel
 * units), clipped to [0, size). Returns 0 if empty. */
static int pixel_span(double lo, double hi, double unit, int size, int *first, int *last)
{
    double f = ceil(lo / unit - 0.5), l = floor(hi / unit - 0.5);
    if (f < 0) f = 0;
    if (l > size - 1) l = size - 1;
    if (f > l) return 0;
    *first = (int)f;
    *last = (int)l;
    return 1;
}

static int is_drawn_side(int area_sign, uint8_t cull)
{
    int front = area_sign < 0; /* counter-clockwise in the world, view y up, screen y down */
    if (cull == TARN_CULL_NONE) return 1;
    return cull == TARN_CULL_FRONT ? !front : front;
}

static int within_exact_range(const ref_screen_vertex v[3], const ref_target *t)
{
    double reach = EXACT_PRODUCT_LIMIT / 2;
    double frame = (t->width > t->height ? t->width : t->height) * t->subpixel_unit;
    for (int i = 0; i < 3; i++)
        if (fabs(v[i].x) + frame >= reach || fabs(v[i].y) + frame >= reach) return 0;
    return 1;
}

/* A 128-bit integer (a GCC and Clang extension, and the host is one of theirs). */
__extension__ typedef __int128 wide_int;

/* The depth test compares near/d rounded to Q1.30, as the header defines the depth
 * buffer. Where the vertex depths are whole Q1.30 numbers (always with the core's own
 * triangles, the snapped mode; by chance otherwise, as on the near plane) and the
 * edge values whole subpixel products, the rounding is done exactly in integers and
 * ties fall exactly as they must; otherwise in doubles. `edge` are the three
 * non-negative edge values of a covered pixel. */
static double depth_q30(const ref_screen_vertex v[3], const double edge[3], double area, int exact)
{
    double z[3];
    int whole = exact;
    for (int k = 0; k < 3; k++) {
        z[k] = v[k].inv_depth * INV_DEPTH_SCALE;
        whole = whole && z[k] == floor(z[k]);
    }
    if (whole) {
        /* Inside the exact range the edges and the area are whole numbers below 2^52
         * (coordinates below 2^25), so sum of edge * z <= area * 2^30 < 2^82: exact
         * in 128 bits. In 64 it overflowed for big unsnapped triangles near the eye. */
        wide_int num = 0;
        const wide_int den = (wide_int)area;
        for (int k = 0; k < 3; k++) num += (wide_int)edge[k] * (wide_int)z[k];
        return (double)((num + den / 2) / den);
    }
    return floor((edge[0] * z[0] + edge[1] * z[1] + edge[2] * z[2]) / area + 0.5);
}

/* The depth buffer holds the opaque pass's depths when the water pass starts, so
 * water is tested against the opaque surface and against earlier water alike. */
static void draw_pixel(ref_target *t, int i, int j, const ref_screen_vertex v[3],
                       const double edge[3], double area, int exact, const tarn_object *obj)
{
    double depth = depth_q30(v, edge, area, exact);
    size_t p = (size_t)j * t->width + i;
    if (!(depth > t->depth[p])) return; /* closer wins; on a tie the earlier stays */
    t->depth[p] = depth;
    ref_pixel px = interpolate(v, edge, area);
    t->inv_depth[p] = px.inv_depth;
    if (obj->material->water != NULL)
        shade_water(t, obj, i, j, &px, t->rgb + 3 * p);
    else
        shade_opaque(&px, obj->material->texture, t->rgb + 3 * p);
    t->surface[p] = (uint32_t)(obj - t->objects) + 1u;
}

/* Draws one triangle with the top-left rule, perspective-correct attributes and
 * the depth test, culled by its snapped screen winding and the material's mode. */
static void rasterize_triangle(ref_target *t, const ref_screen_vertex in[3],
                               const tarn_object *obj)
{
    ref_edge first = make_edge(&in[0], &in[1]);
    int exact = !t->continuous && within_exact_range(in, t);
    double signed_area = edge_value(&first, in[2].x, in[2].y, exact);
    int area_sign = (signed_area > 0) - (signed_area < 0);
    if (area_sign == 0 || !is_drawn_side(area_sign, obj->material->cull)) return;

    /* Wind to positive area so every edge function is positive inside. */
    int flip = area_sign < 0;
    ref_screen_vertex v[3] = { in[0], in[flip ? 2 : 1], in[flip ? 1 : 2] };
    ref_edge edge[3];
    for (int k = 0; k < 3; k++) edge[k] = make_edge(&v[(k + 1) % 3], &v[(k + 2) % 3]);
    double area = fabs(signed_area);

    int i0, i1, j0, j1;
    double unit = t->subpixel_unit;
    if (!pixel_span(fmin(v[0].x, fmin(v[1].x, v[2].x)), fmax(v[0].x, fmax(v[1].x, v[2].x)), unit,
                    t->width, &i0, &i1)
        || !pixel_span(fmin(v[0].y, fmin(v[1].y, v[2].y)), fmax(v[0].y, fmax(v[1].y, v[2].y)), unit,
                       t->height, &j0, &j1))
        return;

    for (int j = j0; j <= j1; j++) {
        double py = (j + 0.5) * unit;
        for (int i = i0; i <= i1; i++) {
            double px = (i + 0.5) * unit;
            double e[3];
            int inside = 1;
            for (int k = 0; k < 3 && inside; k++) {
                /* edge k is opposite vertex k: its value / area is k's barycentric */
                e[k] = edge_value(&edge[k], px, py, exact);
                inside = e[k] > 0 || (e[k] == 0 && edge[k].owns_boundary);
            }
            if (inside) draw_pixel(t, i, j, v, e, area, exact, obj);
        }
    }
}

/* ---- default mode: the whole pipeline in doubles ---------------------------------- */

/* Per-channel light of a world normal: min(1, ambient + light * max(0, N.L)). */
static void light_vertex(const tarn_light *light, tarn_dvec3 normal, double shade[3])
{
    double n_dot_l = fmax(0.0, tarn_dvec_dot(normal, tarn_dvec_from_q16(light->direction)));
    for (int c = 0; c < 3; c++) {
        double lit = tarn_ref_channel(light->ambient_rgb, c) / 255.0
                     + tarn_ref_channel(light->colour_rgb, c) / 255.0 * n_dot_l;
        shade[c] = fmin(1.0, lit);
    }
}

/* (1 - saturate(n.v))^2: n the unit world normal, v the unit vector from the vertex
 * toward the camera (none when they coincide: 0). */
static double vertex_fresnel(const tarn_ref_camera *cam, tarn_dvec3 normal, tarn_dvec3 world)
{
    tarn_dvec3 to_camera = tarn_dvec_sub(cam->position, world);
    if (tarn_dvec_dot(to_camera, to_camera) == 0) return 0.0;
    double n_dot_v = tarn_dvec_dot(tarn_dvec_normalize(normal), tarn_dvec_normalize(to_camera));
    double one_minus = 1.0 - fmin(1.0, fmax(0.0, n_dot_v));
    return one_minus * one_minus;
}

static ref_view_vertex transform_vertex(const tarn_scene *scene, const tarn_ref_camera *cam,
                                        const tarn_object *obj, unsigned index)
{
    const tarn_mesh *mesh = obj->mesh;
    const tarn_material *mat = obj->material;
    ref_view_vertex out;
    tarn_dvec3 world = tarn_ref_world_position(obj, mesh->positions[index]);
    tarn_dvec3 rel = tarn_dvec_sub(world, cam->position);
    out.view[0] = tarn_dvec_dot(rel, cam->right);
    out.view[1] = tarn_dvec_dot(rel, cam->up);
    out.view[2] = tarn_dvec_dot(rel, cam->forward);

    /* Normals are read only where needed: unlit meshes may have none (or too few). */
    double shade[3] = { 1, 1, 1 };
    int fresnel = mat->water != NULL && (mat->water->features & TARN_WATER_FRESNEL);
    tarn_dvec3 normal = { 0, 0, 0 };
    if (!mat->unlit || fresnel) normal = tarn_dvec_rotate(obj->rotation, tarn_dvec_from_q16(mesh->normals[index]));
    if (!mat->unlit) light_vertex(&scene->light, normal, shade);
    out.fresnel = fresnel ? vertex_fresnel(cam, normal, world) : 0.0;
    for (int c = 0; c < 3; c++) {
        double vertex_colour =
            mesh->colours != NULL ? tarn_ref_channel(mesh->colours[index], c) : 255.0;
        out.lit[c] = tarn_ref_channel(mat->colour_rgb, c) * vertex_colour / 255.0 * shade[c];
    }
    out.uv[0] = mesh->uvs != NULL ? mesh->uvs[index].u / Q16_SCALE : 0.0;
    out.uv[1] = mesh->uvs != NULL ? mesh->uvs[index].v / Q16_SCALE : 0.0;
    return out;
}

static ref_view_vertex lerp_view_vertex(const ref_view_vertex *a, const ref_view_vertex *b,
                                        double s)
{
    ref_view_vertex r;
    for (int k = 0; k < 3; k++) r.view[k] = a->view[k] + (b->view[k] - a->view[k]) * s;
    for (int k = 0; k < 3; k++) r.lit[k] = a->lit[k] + (b->lit[k] - a->lit[k]) * s;
    for (int k = 0; k < 2; k++) r.uv[k] = a->uv[k] + (b->uv[k] - a->uv[k]) * s;
    r.fresnel = a->fresnel + (b->fresnel - a->fresnel) * s;
    return r;
}

/* A clipping plane in view space: a point is kept where n . view + offset >= 0. */
typedef struct {
    double n[3], offset;
} ref_clip_plane;

#define CLIP_PLANES 6
#define CLIP_MAX_VERTICES (3 + CLIP_PLANES) /* each plane adds at most one vertex */

static double plane_distance(const ref_clip_plane *plane, const ref_view_vertex *v)
{
    return plane->n[0] * v->view[0] + plane->n[1] * v->view[1] + plane->n[2] * v->view[2] + plane->offset;
}

/* Sutherland-Hodgman against one plane. Returns the new count. A vertex cut on the
 * near or far plane gets that depth exactly, whatever the rounding. */
static int clip_polygon(const ref_view_vertex *in, int count, const ref_clip_plane *plane,
                        ref_view_vertex *out)
{
    int depth_plane = plane->n[0] == 0 && plane->n[1] == 0;
    int n = 0;
    for (int i = 0; i < count; i++) {
        const ref_view_vertex *a = &in[i], *b = &in[(i + 1) % count];
        double da = plane_distance(plane, a), db = plane_distance(plane, b);
        if (da >= 0) out[n++] = *a;
        if ((da >= 0) != (db >= 0)) {
            out[n] = lerp_view_vertex(a, b, da / (da - db));
            if (depth_plane) out[n].view[2] = -plane->offset / plane->n[2];
            n++;
        }
    }
    return n;
}

/* Near and far, then the guard frustum: screen x = width/2 + x focal / d within
 * [-G, width + G] is x focal + (width/2 + G) d >= 0 and -x focal + (width/2 + G) d
 * >= 0, and the same for y. */
static void clip_planes_make(const tarn_ref_camera *cam, const ref_target *t, ref_clip_plane planes[CLIP_PLANES])
{
    double reach_x = t->width / 2.0 + GUARD_BAND_PIXELS, reach_y = t->height / 2.0 + GUARD_BAND_PIXELS;
    const ref_clip_plane all[CLIP_PLANES] = {
        { { 0, 0, 1 }, -cam->near },
        { { 0, 0, -1 }, cam->far },
        { { cam->focal, 0, reach_x }, 0 },
        { { -cam->focal, 0, reach_x }, 0 },
        { { 0, cam->focal, reach_y }, 0 },
        { { 0, -cam->focal, reach_y }, 0 },
    };
    memcpy(planes, all, sizeof all);
}

/* Off any grid: the position as it falls, in units of the finest grid. */
static double screen_coordinate(double pixels, const ref_target *t)
{
    return pixels * t->subpixel_unit;
}

static ref_screen_vertex project(const ref_view_vertex *v, const tarn_ref_camera *cam,
                                 const ref_target *t)
{
    ref_screen_vertex s;
    double d = v->view[2];
    s.x = screen_coordinate(t->width / 2.0 + v->view[0] * cam->focal / d, t);
    s.y = screen_coordinate(t->height / 2.0 - v->view[1] * cam->focal / d, t);
    s.inv_depth = cam->near / d;
    memcpy(s.lit, v->lit, sizeof s.lit);
    memcpy(s.uv, v->uv, sizeof s.uv);
    s.fresnel = v->fresnel;
    return s;
}

static void draw_view_triangle(ref_target *t, const tarn_ref_camera *cam, const ref_view_vertex tri[3],
                               const tarn_object *obj)
{
    ref_clip_plane planes[CLIP_PLANES];
    clip_planes_make(cam, t, planes);
    ref_view_vertex polygon[2][CLIP_MAX_VERTICES];
    memcpy(polygon[0], tri, 3 * sizeof *tri);
    int n = 3;
    for (int k = 0; k < CLIP_PLANES && n > 0; k++) n = clip_polygon(polygon[k & 1], n, &planes[k], polygon[(k + 1) & 1]);
    const ref_view_vertex *clipped = polygon[CLIP_PLANES & 1];
    ref_screen_vertex screen[CLIP_MAX_VERTICES];
    for (int i = 0; i < n; i++) screen[i] = project(&clipped[i], cam, t);
    for (int i = 1; i + 1 < n; i++) {
        ref_screen_vertex fan[3] = { screen[0], screen[i], screen[i + 1] };
        rasterize_triangle(t, fan, obj);
    }
}

/* Whether `obj` draws in this pass: opaque objects first, then water. */
static int in_pass(const tarn_object *obj, int water_pass)
{
    return (obj->material->water != NULL) == (water_pass != 0);
}

static void render_unsnapped(const tarn_scene *scene, ref_target *t, int water_pass)
{
    tarn_ref_camera cam = tarn_ref_camera_make(&scene->camera, t->height);
    for (unsigned o = 0; o < scene->object_count; o++) {
        const tarn_object *obj = &scene->objects[o];
        const tarn_mesh *mesh = obj->mesh;
        if (!in_pass(obj, water_pass)) continue;
        for (unsigned tri = 0; tri < mesh->triangle_count; tri++) {
            ref_view_vertex corner[3];
            for (int k = 0; k < 3; k++)
                corner[k] = transform_vertex(scene, &cam, obj, mesh->indices[3 * tri + k]);
            draw_view_triangle(t, &cam, corner, obj);
        }
    }
}

/* ---- snapped mode: the core's own screen triangles -------------------------------- */

typedef struct {
    ref_target *target;
    int water_pass;
} snapped_pass;

static void visit_core_triangle(void *user, const tarn_screen_vertex vertex[3],
                                const tarn_object *object)
{
    const snapped_pass *pass = user;
    if (!in_pass(object, pass->water_pass)) return;
    ref_screen_vertex v[3];
    for (int k = 0; k < 3; k++) {
        v[k].x = vertex[k].x;
        v[k].y = vertex[k].y;
        v[k].inv_depth = vertex[k].inv_depth / INV_DEPTH_SCALE;
        for (int c = 0; c < 3; c++) v[k].lit[c] = vertex[k].lit[c] / Q8_8_SCALE;
        /* a clipped vertex's coordinates carry 16 bits below Q16.16 */
        v[k].uv[0] = (vertex[k].uv.u + vertex[k].uv_low[0] / Q16_SCALE) / Q16_SCALE;
        v[k].uv[1] = (vertex[k].uv.v + vertex[k].uv_low[1] / Q16_SCALE) / Q16_SCALE;
        v[k].fresnel = vertex[k].fresnel / FRESNEL_SCALE;
    }
    /* The core hands triangles over in their original winding and culls them only in
     * its rasterizer, on the snapped winding (whatever tarn_render.h says of the
     * visitor): cull here by the same rule. Were they culled already, it is a no-op. */
    rasterize_triangle(pass->target, v, object);
}

/* The visitor is walked once per pass and keeps that pass's objects, so the
 * passes hold whatever order the core visits them in. */
static int render_snapped(const tarn_scene *scene, ref_target *t, const tarn_reference_options *opt,
                          int water_pass)
{
    tarn_frame_config config = {
        .width = (uint16_t)t->width,
        .height = (uint16_t)t->height,
        .quality = opt->quality != NULL ? *opt->quality : tarn_quality_default(),
    };
    config.quality.subpixel_bits = (uint8_t)opt->subpixel_bits;
    snapped_pass pass = { t, water_pass };
    return (int)tarn_visit_screen_triangles(scene, &config, visit_core_triangle, &pass);
}

static int render_pass(const tarn_scene *scene, ref_target *t, const tarn_reference_options *opt,
                       int water_pass)
{
    if (opt->geometry == TARN_REF_CORE_TRIANGLES) return render_snapped(scene, t, opt, water_pass);
    render_unsnapped(scene, t, water_pass);
    return TARN_OK;
}

/* ---- water and underwater ---------------------------------------------------------- */

static int has_water(const tarn_scene *scene)
{
    for (unsigned o = 0; o < scene->object_count; o++)
        if (scene->objects[o].material->water != NULL) return 1;
    return 0;
}

/* Linear depth d = near / (near/d) of every pixel; far where nothing was drawn. */
static void linear_depths(const ref_target *t, double *out)
{
    size_t pixels = (size_t)t->width * t->height;
    for (size_t p = 0; p < pixels; p++)
        out[p] = t->inv_depth[p] > 0 ? t->near / t->inv_depth[p] : t->far;
}

/* A copy of the frame's colour and linear depth as drawn so far: what the water
 * pass reads while it draws over the frame, and what the underwater view displaces. */
typedef struct {
    uint8_t *rgb;
    double *depth;
} frame_snapshot;

static int take_snapshot(const ref_target *t, frame_snapshot *snap)
{
    size_t pixels = (size_t)t->width * t->height;
    snap->rgb = malloc(3 * pixels);
    snap->depth = malloc(pixels * sizeof *snap->depth);
    if (snap->rgb == NULL || snap->depth == NULL) return TARN_ERR_MEMORY;
    memcpy(snap->rgb, t->rgb, 3 * pixels);
    linear_depths(t, snap->depth);
    return TARN_OK;
}

static void free_snapshot(frame_snapshot *snap)
{
    free(snap->rgb);
    free(snap->depth);
}

static int render_water(const tarn_scene *scene, ref_target *t, const tarn_reference_options *opt)
{
    frame_snapshot opaque;
    int status = take_snapshot(t, &opaque);
    if (status == TARN_OK) {
        tarn_ref_camera cam = tarn_ref_camera_make(&scene->camera, t->height);
        tarn_ref_water_view view = {
            .width = t->width, .height = t->height, .rgb = opaque.rgb, .depth = opaque.depth,
            .time_ms = opt->time_ms, .light = &scene->light,
            .backward = { -cam.forward.x, -cam.forward.y, -cam.forward.z },
        };
        t->water = &view;
        status = render_pass(scene, t, opt, 1);
        t->water = NULL;
    }
    free_snapshot(&opaque);
    return status;
}

/* The underwater view reads the finished image and the nearest depth, water
 * included. Only a camera below the water plane sees it. */
static int render_underwater(const tarn_scene *scene, ref_target *t, uint32_t time_ms)
{
    const tarn_underwater *u = scene->underwater;
    if (u == NULL || !(scene->camera.position.y < u->level)) return TARN_OK;
    frame_snapshot above;
    int status = take_snapshot(t, &above);
    if (status == TARN_OK)
        tarn_ref_apply_underwater(u, t->width, t->height, time_ms, above.rgb, above.depth, t->rgb);
    free_snapshot(&above);
    return status;
}

/* ---- entry point ------------------------------------------------------------------ */

static void clear_target(ref_target *t, uint32_t background)
{
    size_t pixels = (size_t)t->width * t->height;
    for (size_t p = 0; p < pixels; p++) {
        for (int c = 0; c < 3; c++) t->rgb[3 * p + c] = (uint8_t)tarn_ref_channel(background, c);
        t->depth[p] = 0.0;
        t->inv_depth[p] = 0.0;
    }
    memset(t->surface, 0, pixels * sizeof *t->surface);
}

/* Opaque objects, then water over them, then the underwater view. */
static int render_frame(const tarn_scene *scene, ref_target *t, const tarn_reference_options *opt)
{
    clear_target(t, scene->background_rgb);
    int status = render_pass(scene, t, opt, 0);
    if (status == TARN_OK && has_water(scene)) status = render_water(scene, t, opt);
    if (status == TARN_OK) status = render_underwater(scene, t, opt->time_ms);
    return status;
}

static int options_are_valid(const tarn_reference_options *opt, int width, int height)
{
    return opt != NULL && width >= 1 && height >= 1 && width <= (int)TARN_FRAME_SIZE_MAX
           && height <= (int)TARN_FRAME_SIZE_MAX && opt->subpixel_bits >= (int)TARN_SUBPIXEL_BITS_MIN
           && opt->subpixel_bits <= (int)TARN_SUBPIXEL_BITS_MAX
           && (opt->geometry == TARN_REF_CONTINUOUS || opt->geometry == TARN_REF_CORE_TRIANGLES);
}

/* A moving scene as it stands at the options' time: posed in doubles for the
 * continuous geometry, and by the core for the core's own triangles, whose shading
 * then follows the same pose. */
static int render_posed(const tarn_scene *scene, int width, int height, const tarn_reference_options *opt,
                        uint8_t *rgb, uint32_t *surface)
{
    tarn_object *objects = calloc(scene->object_count + 1u, sizeof *objects);
    if (objects == NULL) return TARN_ERR_MEMORY;
    tarn_scene posed;
    int status = tarn_scene_pose(scene, opt->time_ms, &posed, objects);
    if (status == TARN_OK && opt->geometry == TARN_REF_CONTINUOUS)
        tarn_ref_scene_pose(scene, opt->time_ms, &posed, objects);
    if (status == TARN_OK) status = tarn_reference_render_surfaces(&posed, width, height, opt, rgb, surface);
    free(objects);
    return status;
}

/* The continuous geometry keeps positions in subpixel units of the finest grid
 * only so that the rasterizer reads one unit; nothing is rounded to it. */
int tarn_reference_render_surfaces(const tarn_scene *scene, int width, int height,
                                   const tarn_reference_options *opt, uint8_t *rgb,
                                   uint32_t *surface)
{
    if (rgb == NULL || surface == NULL || !options_are_valid(opt, width, height)) return TARN_ERR_CONFIG;
    if (!scene_is_valid(scene)) return TARN_ERR_SCENE;
    if (tarn_scene_moves(scene)) return render_posed(scene, width, height, opt, rgb, surface);

    size_t pixels = (size_t)width * height;
    int continuous = opt->geometry == TARN_REF_CONTINUOUS;
    ref_target t = {
        .width = width, .height = height,
        .subpixel_unit = ldexp(1.0, continuous ? (int)TARN_SUBPIXEL_BITS_MAX : opt->subpixel_bits),
        .continuous = continuous, .rgb = rgb, .surface = surface, .objects = scene->objects,
        .depth = malloc(pixels * sizeof *t.depth),
        .inv_depth = malloc(pixels * sizeof *t.inv_depth),
        .near = scene->camera.near / Q16_SCALE, .far = scene->camera.far / Q16_SCALE,
        .camera = tarn_ref_camera_make(&scene->camera, height),
        .plane_coordinates = continuous || (opt->quality != NULL ? opt->quality->water_coordinates
                                                                 : tarn_quality_default().water_coordinates) ==
                                               TARN_WATER_UV_PLANE,
    };
    int status = TARN_ERR_MEMORY;
    if (t.depth != NULL && t.inv_depth != NULL) status = render_frame(scene, &t, opt);
    free(t.depth);
    free(t.inv_depth);
    return status;
}

int tarn_reference_render(const tarn_scene *scene, int width, int height,
                          const tarn_reference_options *opt, uint8_t *rgb, uint8_t *covered)
{
    if (width < 1 || height < 1 || width > (int)TARN_FRAME_SIZE_MAX || height > (int)TARN_FRAME_SIZE_MAX)
        return TARN_ERR_CONFIG;
    size_t pixels = (size_t)width * height;
    uint32_t *surface = malloc(pixels * sizeof *surface);
    if (surface == NULL) return TARN_ERR_MEMORY;
    int status = tarn_reference_render_surfaces(scene, width, height, opt, rgb, surface);
    if (status == TARN_OK && covered != NULL)
        for (size_t p = 0; p < pixels; p++) covered[p] = surface[p] != 0;
    free(surface);
    return status;
}
