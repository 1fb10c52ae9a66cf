/* key_curve.c: a tarn_key_curve's value at a time (tarn_motion.h): the Hermite
 * curve through the keys with Catmull-Rom tangents, in 64-bit sums of Q2.30
 * weights. Once a frame per curve. */
#include "scene/scene_internal.h"

#define ONE_Q30 ((int64_t)1 << 30)

/* Key i's time, for i from -1 to key_count: a looping curve's keys repeat every
 * loop_ms either side; a clamped curve's ends stand for the keys beyond them. */
static int64_t key_time(const tarn_key_curve *c, int32_t i)
{
    const int32_t n = c->key_count;
    if (c->loop_ms == 0u) return c->times_ms[tarn_clamp_i32(i, 0, n - 1)];
    if (i < 0) return (int64_t)c->times_ms[i + n] - c->loop_ms;
    if (i >= n) return (int64_t)c->times_ms[i - n] + c->loop_ms;
    return c->times_ms[i];
}

static int32_t key_value(const tarn_key_curve *c, int32_t i, unsigned channel)
{
    const int32_t n = c->key_count;
    /* i lies within a key of the ends: a looping curve's wraps once at most (and
     * without %, which a Cortex-M0 takes from libgcc) */
    const int32_t k = c->loop_ms == 0u ? tarn_clamp_i32(i, 0, n - 1) : (i < 0 ? i + n : (i >= n ? i - n : i));
    return c->values[(uint32_t)k * c->channels + channel];
}

/* n / d in Q2.30, for 0 <= n <= d, d > 0 and below 2^33: exact to the floor. */
static int64_t ratio_q30(int64_t n, int64_t d)
{
    /* d halved until it fits 32 bits, n with it: 2^-30 is coarser than what that loses */
    while (d >= ((int64_t)1 << 32)) {
        n /= 2;
        d /= 2;
    }
    const tarn_divisor divisor = tarn_divisor_of((uint32_t)d);
    return (int64_t)tarn_divide_u64((uint64_t)n << 30, &divisor, 0);
}

/* The segment [k, k+1] the time lies in (key k + 1 may be the first key again, a
 * loop later), with the time on the curve's own clock; -1 or key_count - 1 when a
 * clamped curve holds an end. */
static int32_t segment_of(const tarn_key_curve *c, uint32_t time_ms, int64_t *t)
{
    const int32_t n = c->key_count;
    *t = c->loop_ms != 0u ? time_ms % c->loop_ms : time_ms;
    if (*t < c->times_ms[0]) {
        if (c->loop_ms == 0u) return -1;
        *t += c->loop_ms; /* on the wrap from the last key to the first */
        return n - 1;
    }
    int32_t k = 0;
    while (k + 1 < n && c->times_ms[k + 1] <= *t) k++;
    return k;
}

/* h times the velocity at key i, for the segment of length h: the Catmull-Rom
 * tangent (key_value(i + 1) - key_value(i - 1)) * h / (t(i + 1) - t(i - 1)). */
static int64_t tangent_term(const tarn_key_curve *c, int32_t i, unsigned channel, int64_t h)
{
    int32_t before = i - 1, after = i + 1;
    if (c->loop_ms == 0u) { /* one-sided at the ends */
        before = tarn_clamp_i32(before, 0, c->key_count - 1);
        after = tarn_clamp_i32(after, 0, c->key_count - 1);
    }
    const int64_t span = key_time(c, after) - key_time(c, before);
    const int64_t rise = (int64_t)key_value(c, after, channel) - key_value(c, before, channel);
    return tarn_round_shift_i64(rise * ratio_q30(h, span), 30);
}

void tarn__key_curve_at(const tarn_key_curve *c, uint32_t time_ms, int32_t *out)
{
    int64_t t;
    const int32_t k = segment_of(c, time_ms, &t);
    const int32_t n = c->key_count;
    if (n == 1 || k < 0 || (k == n - 1 && c->loop_ms == 0u)) { /* a key held */
        for (unsigned ch = 0; ch < c->channels; ch++) out[ch] = key_value(c, k, ch);
        return;
    }
    const int64_t h = key_time(c, k + 1) - key_time(c, k);
    const int64_t s = ratio_q30(t - key_time(c, k), h);
    const int64_t s2 = tarn_round_shift_i64(s * s, 30);
    const int64_t s3 = tarn_round_shift_i64(s2 * s, 30);
    const int64_t h00 = 2 * s3 - 3 * s2 + ONE_Q30, h10 = s3 - 2 * s2 + s;
    const int64_t h01 = -2 * s3 + 3 * s2, h11 = s3 - s2;
    for (unsigned ch = 0; ch < c->channels; ch++) {
        const int64_t sum = key_value(c, k, ch) * h00 + key_value(c, k + 1, ch) * h01 +
                            tangent_term(c, k, ch, h) * h10 + tangent_term(c, k + 1, ch, h) * h11;
        out[ch] = tarn_sat_i64_to_i32(tarn_round_shift_i64(sum, 30));
    }
}

int tarn__key_curve_valid(const tarn_key_curve *c, unsigned channels)
{
    if (c->key_count < 1u || c->key_count > TARN_KEYS_MAX || c->channels != channels ||
        c->times_ms == NULL || c->values == NULL)
        return 0;
    for (uint32_t i = 1; i < c->key_count; i++)
        if (c->times_ms[i] <= c->times_ms[i - 1]) return 0;
    return c->loop_ms == 0u || c->times_ms[c->key_count - 1] < c->loop_ms;
}
