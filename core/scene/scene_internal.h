/* scene_internal.h: the first stage of a frame (core/scene/), internal to core/.
 *
 * Before anything is drawn: the frame config and the scene data are checked, so
 * that no later stage reads outside an array or meets a number out of range; and
 * what a scene's numbers decide for the whole frame is found: whether its static
 * view and backdrop apply, how far refraction and the underwater view reach, and
 * with that the apron each tile draws around itself. Nothing here runs per pixel. */
#ifndef TARN_SCENE_INTERNAL_H
#define TARN_SCENE_INTERNAL_H

#include "tarn/tarn_motion.h"
#include "tarn/tarn_render.h"

/* A bit above 0x00RRGGBB that a water pass drawing in place over the opaque
 * buffers sets on the pixels it writes (core/water/), and clears before the sink
 * sees the tile; no backdrop colour may hold it. */
#define TARN_WATER_MARK 0x01000000u

/* Whether a depth buffer of the quality's depth_bits holds 16-bit codes: known when
 * the build links one form only (tarn_config.h), so a pixel need not ask. */
static inline int tarn__depth_is_16_bits(unsigned depth_bits)
{
    return TARN_LINK_DEPTH16 && (!TARN_LINK_DEPTH32 || depth_bits == 16u);
}

/* Validates a frame config; TARN_OK or TARN_ERR_CONFIG (config_check.c). */
tarn_status tarn__config_check(const tarn_frame_config *config);

/* Validates the scene's arrays so the walk never reads past them (scene_check.c). */
tarn_status tarn__scene_check(const tarn_scene *scene);
/* TARN_ERR_SCENE when a water material's refraction reaches past the widest apron,
 * when the scene has a backdrop that does not apply to the frame, or when its water
 * needs shading this build left out. */
tarn_status tarn__scene_check_reach(const tarn_scene *scene, const tarn_frame_config *config);

/* 1 when the scene has a static view and its camera and light are that view's
 * (static_view.c). */
int tarn__static_view_applies(const tarn_scene *scene);
/* 1 when moreover the frame is the static view's: its screen positions and bins hold. */
int tarn__static_screen_applies(const tarn_scene *scene, const tarn_frame_config *config);

/* The scene's backdrop when it applies to the frame (the static view's screen, the
 * quality it was drawn at), else NULL; whether its arrays hold what it says for the
 * static view's frame and the scene's objects (backdrop_check.c). */
const tarn_backdrop *tarn__backdrop_for(const tarn_scene *scene, const tarn_frame_config *config);
int tarn__backdrop_valid(const tarn_backdrop *backdrop, const tarn_scene *scene);

/* Motion (motion.c, key_curve.c; tarn_motion.h). */
/* 1 when every motion of the scene keeps tarn_motion.h's rules. */
int tarn__motion_valid(const tarn_scene *scene);
/* 1 when the camera or the light moves: no static view applies then. */
int tarn__view_moves(const tarn_scene *scene);
/* 1 when some object moves. */
int tarn__objects_move(const tarn_scene *scene);
/* tarn_scene_pose for a checked scene; `objects` NULL when no object moves (the
 * posed scene then keeps the scene's). */
void tarn__scene_pose(const tarn_scene *scene, uint32_t time_ms, tarn_scene *posed, tarn_object *objects);
/* The curve's value at time_ms, its channels into out. */
void tarn__key_curve_at(const tarn_key_curve *curve, uint32_t time_ms, int32_t *out);
/* 1 when the curve keeps tarn_key_curve's rules with this many channels. */
int tarn__key_curve_valid(const tarn_key_curve *curve, unsigned channels);

/* How far the water reaches (reach.c; tarn_water_reach_pixels and
 * tarn_frame_apron_pixels are public). */
/* 1 when some object of the scene has a water material. */
int tarn__scene_has_water(const tarn_scene *scene);
/* A reach in pixels, cut to the quality's apron width and to TARN_WATER_APRON_MAX. */
int32_t tarn__apron_limit(int32_t reach, const tarn_quality *quality);
/* 1 when the view is under water: the scene has an underwater block and the
 * camera is below its level. */
int tarn__underwater_active(const tarn_scene *scene);
/* Pixels the underwater displacement can reach at this frame width. */
int32_t tarn__underwater_reach_pixels(const tarn_underwater *under, uint16_t frame_width);

#endif
