/* tarn_motion.h: scenes that move with the frame's clock.
 *
 * A scene's camera may follow a path, its light may turn, and each object may bob,
 * spin and follow a path, all as functions of the frame's time_ms (tarn_render.h).
 * tarn_render_frame poses the scene for its time before it draws (tarn_scene_pose,
 * in integers); the float reference (host/reference/ref_motion.c) poses it by the
 * same formulas in doubles. Nothing is kept between frames: a frame at time t is the
 * same whatever frames came before it.
 *
 * Every periodic motion turns by its phase, the share of its period elapsed:
 *   phase(t, period) = (t mod period_ms) / period_ms   (found to 2^-32 of a turn)
 * and angles are in turns (1 = 360 degrees), so a motion repeats exactly.
 *
 * Keyframes (tarn_key_curve) are joined by a cubic Hermite curve whose tangent at
 * each key is the Catmull-Rom one for uneven times, the velocity
 *   m_k = (p[k+1] - p[k-1]) / (t[k+1] - t[k-1]),
 * so the curve passes through every key with a continuous velocity. Between keys k
 * and k+1, with s = (t - t[k]) / (t[k+1] - t[k]) and h = t[k+1] - t[k]:
 *   p(t) = (2s^3 - 3s^2 + 1) p[k] + (s^3 - 2s^2 + s) h m_k
 *        + (-2s^3 + 3s^2) p[k+1] + (s^3 - s^2) h m_(k+1).
 * A clamped curve (loop_ms 0) holds its first key before it and its last after it,
 * and its end tangents are one-sided: m_0 = (p[1] - p[0]) / (t[1] - t[0]), and the
 * same at the last key. A looping curve repeats every loop_ms: time is taken modulo
 * loop_ms, and the curve runs on from its last key back to its first at time
 * t[0] + loop_ms, the keys around the ends wrapping for the tangents. One key is a
 * constant. */
#ifndef TARN_MOTION_H
#define TARN_MOTION_H

#include <stdint.h>
#include "tarn_fixed.h"
#include "tarn_render.h"
#include "tarn_scene.h"

#ifdef __cplusplus
extern "C" {
#endif

#define TARN_KEYS_MAX 256u
#define TARN_KEY_CHANNELS_MAX 7u

/* Values at times, and the curve through them (above). */
typedef struct {
    const uint32_t *times_ms; /* key_count, strictly ascending; with loop_ms, each
                                 below loop_ms */
    const tarn_q16 *values;   /* key_count * channels, one key's after another;
                                 Q16.16 world units (or degrees, for a fov) */
    uint16_t key_count;       /* 1..TARN_KEYS_MAX */
    uint8_t channels;         /* 1..TARN_KEY_CHANNELS_MAX */
    uint32_t loop_ms;         /* 0: clamped; else the period it repeats with */
} tarn_key_curve;

typedef enum {
    TARN_CAMERA_ORBIT = 1, /* circles a centre */
    TARN_CAMERA_KEYS = 2   /* follows keyframes */
} tarn_camera_path_kind;

/* The camera's path. The scene's camera gives what the path leaves alone: near, far,
 * and (without a fov channel) the field of view. */
struct tarn_camera_path {
    uint8_t kind;            /* tarn_camera_path_kind */
    /* TARN_CAMERA_ORBIT: at angle a = start + phase(t, period) turns (minus it when
     * clockwise seen from above), the camera stands at
     *   centre + (radius * sin(2 pi a), height, radius * cos(2 pi a))
     * and looks at `target`. */
    tarn_vec3 centre;        /* Q16.16 world */
    tarn_q16 radius;         /* Q16.16 world units, > 0 */
    tarn_q16 height;         /* Q16.16 world units above the centre */
    uint32_t period_ms;      /* > 0: one turn */
    uint32_t start_turns_q32; /* Q0.32 turns: the angle at time 0 */
    uint8_t clockwise;       /* 1: the angle falls with time */
    tarn_vec3 target;        /* Q16.16 world, never on the orbit */
    /* TARN_CAMERA_KEYS: 6 channels (position x, y, z, target x, y, z) or 7 (and the
     * vertical fov in degrees, clamped to 1..179); position and target distinct at
     * every key */
    tarn_key_curve keys;
};

/* An object's motion. Its world transform at time t is
 *   world = position(t) + scale * spin(t) * rotation * object point
 *   position(t) = (path ? path(t) : position) + bob * sin(2 pi (phase(t, bob_period) + bob_phase))
 * spin(t) the rotation by phase(t, spin_period) turns about spin_axis, counter-
 * clockwise seen from the axis's tip (the right-hand rule). Each part is off while
 * its period (or key count) is 0. The object then has no static vertices. */
struct tarn_object_motion {
    tarn_vec3 bob;             /* Q16.16 world offset at the crest (axis times amplitude) */
    uint32_t bob_period_ms;
    uint32_t bob_phase_q32;    /* Q0.32 turns */
    tarn_vec3 spin_axis;       /* Q16.16 unit world axis */
    uint32_t spin_period_ms;
    tarn_key_curve path;       /* 3 channels: world position; key_count 0: none */
};

/* The light's motion: its direction turned about spin_axis as an object spins, after
 * following its keyframes (3 channels, a direction, normalised) if it has any. */
struct tarn_light_motion {
    tarn_vec3 spin_axis;       /* Q16.16 unit world axis */
    uint32_t spin_period_ms;   /* 0: no spin */
    tarn_key_curve direction;  /* key_count 0: the scene's light direction */
};

/* Whether anything in the scene moves. */
int tarn_scene_moves(const tarn_scene *scene);

/* The scene as it stands at time_ms: `posed` is a copy of the scene with its camera
 * and light at that time and its objects `objects` (object_count entries the caller
 * provides), each with its transform at that time and no motion. Nothing in the
 * copy moves; it holds the scene's static view only if the camera and light never
 * move. tarn_render_frame does this itself, in its memory. Returns TARN_ERR_SCENE for
 * a motion that breaks the rules above (tarn_render_frame refuses such a scene too). */
tarn_status tarn_scene_pose(const tarn_scene *scene, uint32_t time_ms, tarn_scene *posed, tarn_object *objects);

#ifdef __cplusplus
}
#endif

#endif
