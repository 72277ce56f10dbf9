/*
 * tfit_internal.h — helpers shared by the target sources (not installed).
 *
 * Everything here is freestanding C11.  Selections are done with bit masks
 * rather than branches so that the instruction stream of an evaluation does
 * not depend on the input value (docs/header-format.md, "Fixed cost").
 */
#ifndef TFIT_INTERNAL_H
#define TFIT_INTERNAL_H

#include <float.h>
#include <stdint.h>

#include "tfit.h"

/* Bit-exactness needs a*b + c rounded twice, as written: no contraction into
 * a fused multiply-add, whatever the caller's flags (GCC's default
 * -std=gnu11 mode contracts on any FPU with FMA, Cortex-M4F included).  GCC
 * honours its optimize pragma even under -ffp-contract=fast; Clang and other
 * C99 compilers honour the standard pragma (GCC does not, and warns).
 * tfit_model_check() proves the result on the device (TFIT_ERR_ARITH). */
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC optimize("fp-contract=off")
#else
#pragma STDC FP_CONTRACT OFF
#endif
/* -ffast-math reassociates and drops NaN and signed-zero handling: no pragma
 * undoes all of it. */
#if defined(__FAST_MATH__)
#error "tfit: -ffast-math changes float results; build the library without it (docs/firmware.md §2)"
#endif

/* Bit-exactness needs float expressions evaluated in float (no x87 excess
 * precision); see GUIDE §4 and docs/header-format.md.  16 (ISO/IEC TS
 * 18661-3: only _Float16 is widened, to float) is as good as 0 for us. */
#if !defined(FLT_EVAL_METHOD) || (FLT_EVAL_METHOD != 0 && FLT_EVAL_METHOD != 16)
#error "tfit requires FLT_EVAL_METHOD == 0 (float arithmetic evaluated in float)"
#endif

/* Number of basis terms of total degree <= p in 3 variables: C(p+3, 3). */
#define TFIT_TERMS(p) ((((p) + 1u) * ((p) + 2u) * ((p) + 3u)) / 6u)
#define TFIT_MAX_TERMS TFIT_TERMS((uint32_t)TFIT_MAX_DEGREE)
#define TFIT_ZHOU_MAX_ROWS (2u * TFIT_ZHOU_MAX_ORDER + 1u)
/* Largest n_out accepted: keeps every size computation inside uint32_t. */
#define TFIT_MAX_OUT (1u << 20)

typedef union tfit_fu {
    float f;
    uint32_t u;
} tfit_fu;

static inline uint32_t tfit_bits(float x)
{
    tfit_fu v;
    v.f = x;
    return v.u;
}

static inline float tfit_float(uint32_t u)
{
    tfit_fu v;
    v.u = u;
    return v.f;
}

/* All ones when the condition holds, else zero. */
static inline uint32_t tfit_mask(int cond)
{
    return 0u - (uint32_t)(cond != 0);
}

/* mask ? a : b, bitwise. */
static inline float tfit_select(uint32_t mask, float a, float b)
{
    return tfit_float((tfit_bits(a) & mask) | (tfit_bits(b) & ~mask));
}

/* x with its bits and-ed with keep: x itself, or +0.0f when keep is 0. */
static inline float tfit_masked(float x, uint32_t keep)
{
    return tfit_float(tfit_bits(x) & keep);
}

/* |x|, by clearing the sign bit. */
static inline float tfit_abs(float x)
{
    return tfit_float(tfit_bits(x) & 0x7fffffffu);
}

static inline uint32_t tfit_umax(uint32_t a, uint32_t b)
{
    return a ^ ((a ^ b) & tfit_mask(a < b));
}

static inline uint32_t tfit_umin(uint32_t a, uint32_t b)
{
    return a ^ ((a ^ b) & tfit_mask(b < a));
}

/* 1/sqrt(s) for a positive normal float s: a start from the bit pattern of
 * s (relative error <= 3.5 % for every positive float), then three Newton
 * steps y <- (y/2)(3 - s y y), each squaring the error (header-format.md §4
 * step 8).  For the region models; tfit_input.c keeps its own copy, so that
 * the input map's code, whose instructions the cycle model counts
 * (host/cost/cycles.c), stays as it is. */
static inline float tfit_rsqrt_step(float s, float y)
{
    float t = s * y;
    t = t * y;
    t = 3.0f - t;
    return (0.5f * y) * t;
}

static inline float tfit_rsqrt(float s)
{
    float y = tfit_float(0x5f3759dfu - (tfit_bits(s) >> 1));
    y = tfit_rsqrt_step(s, y);
    y = tfit_rsqrt_step(s, y);
    return tfit_rsqrt_step(s, y);
}

/* Chebyshev series without its constant term, sum_{k=1..n} c_k T_k(x), by
 * Clenshaw's recurrence (docs/header-format.md §5.4):
 *   h = x + x; b_{n+1} = b_{n+2} = +0;
 *   b_k = ((h b_{k+1}) - b_{k+2}) + c_k, k = n .. 1;
 *   result (x b_1) - b_2.
 * n steps, and the same instruction path for every n, 0 included (then the
 * result is x * 0 - 0, a zero): the zhou2017 orders may be 0, and a branch
 * on them would give the cycle model one more path to describe. */
static inline float tfit_cheb_tail(const float *c, uint32_t n, float x)
{
    const float h = x + x;
    float b1 = 0.0f;
    float b2 = 0.0f;
    for (uint32_t k = n; k > 0u; --k) {
        const float b = (h * b1 - b2) + c[k];
        b2 = b1;
        b1 = b;
    }
    return x * b1 - b2;
}

/* Chebyshev series sum_{k=0..n} c_k T_k(x): tail + c_0 (c_0 exactly, up to
 * the sign of a zero c_0, when n = 0). */
static inline float tfit_cheb(const float *c, uint32_t n, float x)
{
    return tfit_cheb_tail(c, n, x) + c[0];
}

/* Dot product of a coefficient row with the basis, phi[0] == 1:
 * c0 + c1 phi1 + ... summed left to right. */
static inline float tfit_row(const float *c, const float *phi, uint32_t n)
{
    float acc = c[0];
    for (uint32_t t = 1u; t < n; ++t) {
        acc = acc + c[t] * phi[t];
    }
    return acc;
}

/* The modal rows in C (header-format.md §5.3), any rank, every target: per
 * output point, out = ((U[0] a_0 + U[1] a_1) + ...) for its three rows,
 * which share each amplitude; the output mask (§5.5) applied as each word
 * is stored.  The modal family's, and the region surfaces' (§5.11). */
static inline void tfit_modal_rows_c(const float *u, const float *a, uint32_t r, uint32_t n_out,
                                     uint32_t keep, float *out)
{
    for (uint32_t j = 0u; j < n_out; ++j) {
        const float *uy = u + r;
        const float *uz = uy + r;
        float x = u[0] * a[0], y = uy[0] * a[0], z = uz[0] * a[0];
        for (uint32_t k = 1u; k < r; ++k) {
            x = x + u[k] * a[k];
            y = y + uy[k] * a[k];
            z = z + uz[k] * a[k];
        }
        out[0] = tfit_masked(x, keep);
        out[1] = tfit_masked(y, keep);
        out[2] = tfit_masked(z, keep);
        u += 3u * r;
        out += 3;
    }
}

/* Degree-1 rows (nodal and contact p = 1, header-format.md §5.2): per output
 * point, out = ((C0 + C1 g0) + C2 g1) + C3 g2 for its three rows.  The basis
 * {1, g0, g1, g2} is g itself (phi_k = g_v * 1.0f is exact), so g is used
 * directly.  One output point per iteration: the three rows of a node share
 * each g_v and keep three independent sums in flight.  The output mask
 * (header-format.md §5.5) is applied as each word is stored.  The portable
 * degree-1 path of tfit_eval.c; on Cortex-M4F/M7 the assembly of
 * tfit_degree1_armv7em.c does the same operations. */
static inline void tfit_rows_degree1(const float *c, const float g[3], uint32_t n_out,
                                     uint32_t keep, float *out)
{
    const float g0 = g[0], g1 = g[1], g2 = g[2];
    for (uint32_t j = 0u; j < n_out; ++j) {
        float x = c[0] + c[1] * g0;
        float y = c[4] + c[5] * g0;
        float z = c[8] + c[9] * g0;
        x = x + c[2] * g1;
        y = y + c[6] * g1;
        z = z + c[10] * g1;
        x = x + c[3] * g2;
        y = y + c[7] * g2;
        z = z + c[11] * g2;
        out[0] = tfit_masked(x, keep);
        out[1] = tfit_masked(y, keep);
        out[2] = tfit_masked(z, keep);
        c += 12;
        out += 3;
    }
}

/* Degree-1 models on Armv7E-M with a single-precision FPU (Cortex-M4F, M7)
 * run in assembly (tfit_degree1_armv7em.c); -DTFIT_PORTABLE selects the C
 * path everywhere, and it is the path on every other target. */
#if defined(__ARM_ARCH_7EM__) && defined(__thumb2__) && defined(__ARM_FP) &&                     \
    ((__ARM_FP & 4) != 0) && !defined(TFIT_PORTABLE)
#define TFIT_DEGREE1_ASM 1
/* The whole evaluation of a degree-1 model: projection (§4), rows (§5.2) and
 * output mask (§5.5); returns the status.  _one: exactly one output point
 * (the contact family), without the registers the pair loop needs. */
tfit_status tfit_degree1_asm(const tfit_model *m, const float in[3], float *out);
tfit_status tfit_degree1_one_asm(const tfit_model *m, const float in[3], float *out);
/* The rows alone (§5.2, §5.5) at g: the model's rows when keep is all ones,
 * the zero rows when it is 0. */
void tfit_degree1_rows_asm(const float *rows, const float g[3], uint32_t n_out, uint32_t keep,
                           float *out);
/* The modal family's output rows at rank r = 1 .. TFIT_MODAL_ASM_MAX_RANK
 * (tfit_modal_armv7em.c): a[r] the amplitudes (+0.0f for a NaN/Inf input),
 * rows the model's U, n_out >= 1 points; keep all ones, or 0 to write the
 * +0.0f of the output mask. */
#define TFIT_MODAL_ASM_MAX_RANK 8u
void tfit_modal_rows_asm(uint32_t r, const float *rows, const float *a, uint32_t n_out,
                         uint32_t keep, float *out);
/* The modal_q15 family in assembly (tfit_modal_q15_armv7em.c), in an
 * optimised build only: without optimisation r7 is the Thumb frame
 * pointer, which the assembly uses (-O0 takes the C, bit for bit the
 * same).  The
 * amplitudes, their Q15 words and the bias word into c[5] (and-ed with
 * keep); the rows of n_out >= 1 points (header-format.md §5.9). */
#if defined(__OPTIMIZE__)
#define TFIT_Q15_ASM 1
#else
#define TFIT_Q15_ASM 0
#endif
void tfit_q15_amp_asm(const float *at, const float *phi, uint32_t n_terms, const float *v,
                      uint32_t keep, uint32_t c[5]);
void tfit_q15_rows_asm(const float *rows, const uint32_t c[5], uint32_t n_out, float scale,
                       float *out);
#else
#define TFIT_DEGREE1_ASM 0
#define TFIT_Q15_ASM 0
#endif

/* Maps the raw input onto the unit ball (tfit_input.c).  Returns an all-ones
 * mask when the input was projected; *bad is all ones when the input held a
 * NaN or Inf (g is then computed from a zero input). */
uint32_t tfit_input_map(const float *map, const float x[3], float g[3], uint32_t *bad);

/* Chebyshev basis of total degree p in g, graded order (tfit_basis.c). */
void tfit_basis(uint32_t p, const float g[3], float *phi);

/* Family evaluators: g on the unit ball -> out[3 n_out] (tfit_nodal.c,
 * tfit_modal.c, tfit_zhou2017.c).  Nodal and modal store every output and-ed
 * with keep (all ones, or zero for a NaN/Inf input: header-format.md §5.5);
 * zhou2017 accumulates into out, so tfit_eval.c masks after it. */
void tfit_eval_nodal(const tfit_model *m, const float g[3], uint32_t keep, float *out);
void tfit_eval_modal(const tfit_model *m, const float g[3], uint32_t keep, float *out);
void tfit_eval_zhou2017(const tfit_model *m, const float g[3], float *out);
void tfit_eval_modal_q15(const tfit_model *m, const float g[3], uint32_t keep, float *out);

/* The cut family (tfit_cut.c, header-format.md §5.7): s -> the knot j and
 * weight w of its interval (s clamped onto [0, 1]; returns all ones when
 * it was clamped, *bad all ones for NaN/Inf, taken as 0); and output
 * points first .. first + count - 1 at the basis phi, and-ed with keep. */
uint32_t tfit_cut_progress(float s, uint32_t intervals, uint32_t *knot, float *w, uint32_t *bad);
void tfit_cut_rows(const tfit_model *m, const float *phi, uint32_t knot, float w, uint32_t first,
                   uint32_t count, uint32_t keep, float *out);

/* h clamped to [-1, 1] (beyond it, +-1 with h's sign) by a bitwise
 * selection: the stateful families' input to their static map. */
static inline float tfit_clamp_unit(float h)
{
    const uint32_t b = tfit_bits(h);
    const uint32_t over = tfit_mask((b & 0x7fffffffu) > 0x3f800000u);
    return tfit_float((b & ~over) | (((b & 0x80000000u) | 0x3f800000u) & over));
}

/* a when the mask is all ones, else b, for pointers (no branch): a stateful
 * family writes its new state into the caller's state or a scratch copy. */
static inline float *tfit_select_ptr(uint32_t mask, float *a, float *b)
{
    const uintptr_t m = (uintptr_t)0 - (uintptr_t)(mask & 1u);
    return (float *)(((uintptr_t)a & m) | ((uintptr_t)b & ~m));
}

/* ---- the stateful forms (tfit_stateful.c, docs/header-format.md §5.6, §5.8):
 * one stepping path, a filter per form.  A filter's K terms take `floats`
 * table floats each after the input map (the static map's tables follow
 * them) and `words` state words each after gp[3]. */
typedef struct tfit_filter {
    uint32_t floats;    /* table floats per term */
    uint32_t words;     /* state words per term */
    uint32_t max_terms; /* K at most */
} tfit_filter;

/* The filters (tfit_prony.c, tfit_resonant.c): the projected input g of
 * this tick -> h, the input of the static map; the new state is written
 * over state when keep is all ones, else into a scratch copy (state keeps
 * every bit).  _terms_ok: the terms within the bounds that keep the state
 * finite (tfit_model_check). */
extern const tfit_filter tfit_filter_prony, tfit_filter_resonant;
void tfit_prony_filter(const tfit_model *m, const float g[3], uint32_t keep, float *state,
                       float h[3]);
void tfit_resonant_filter(const tfit_model *m, const float g[3], uint32_t keep, float *state,
                          float h[3]);
int tfit_prony_terms_ok(const tfit_model *m);
int tfit_resonant_terms_ok(const tfit_model *m);

/* The filter of a stateful family, or NULL for any other family (inline:
 * each tick asks it for the static map's offset). */
static inline const tfit_filter *tfit_filter_of(uint32_t family)
{
    switch (family) {
    case TFIT_FAMILY_PRONY:
        return &tfit_filter_prony;
    case TFIT_FAMILY_RESONANT:
        return &tfit_filter_resonant;
    default:
        return 0;
    }
}
/* For a stateful model only: its filter (by its family); its terms within
 * their bounds (1, else 0); its state words, gp included; its static map
 * as a nodal (dims[1] = 0) or modal model *v (the fields the evaluators
 * read: family, n_out, n_dims, dims, coef, n_coef, node_ids); and that map
 * at h, outputs and-ed with keep (the degree-1 assembly for p = 1 nodal
 * maps on Armv7E-M). */
void tfit_stateful_filter(const tfit_model *m, const float g[3], uint32_t keep, float *state,
                          float h[3]);
int tfit_stateful_terms_ok(const tfit_model *m);
uint32_t tfit_stateful_words(const tfit_model *m);
void tfit_stateful_static(const tfit_model *m, tfit_model *v);
void tfit_stateful_eval(const tfit_model *v, const float h[3], uint32_t keep, float *out);
/* A stateful form's public reset, for a model of the given family
 * (tfit.h: TFIT_ERR_ARG for a NULL argument or table, TFIT_ERR_FAMILY for
 * another family). */
tfit_status tfit_stateful_reset(uint32_t family, const tfit_model *m, float *state);
/* The checks of a stateful form's public step, in the order of tfit.h:
 * TFIT_ERR_ARG for a NULL argument or table, TFIT_ERR_FAMILY for a model
 * of another family, else TFIT_OK.  Inline, so that the step goes on to
 * tfit_stateful_step() as a tail call. */
static inline tfit_status tfit_stateful_refuse(uint32_t family, const tfit_model *m,
                                               const float *state, const float *force,
                                               const float *out)
{
    if ((m == 0) | (state == 0) | (force == 0) | (out == 0)) {
        return TFIT_ERR_ARG;
    }
    if ((m->dims == 0) | (m->coef == 0)) {
        return TFIT_ERR_ARG;
    }
    return m->family != family ? TFIT_ERR_FAMILY : TFIT_OK;
}
/* One tick of a checked stateful model (docs/header-format.md §5.6, §5.8). */
tfit_status tfit_stateful_step(const tfit_model *m, float *state, const float force[3],
                               float *out);
/* State words of any stateful model, at most. */
#define TFIT_STATEFUL_MAX_STATE TFIT_RESONANT_MAX_STATE
_Static_assert(TFIT_PRONY_MAX_STATE <= TFIT_STATEFUL_MAX_STATE, "stateful state capacity");
_Static_assert(TFIT_PRONY_DIMS == TFIT_RESONANT_DIMS, "the stateful forms share their dims");

/* CRC-32 (IEEE, reflected) of one little-endian word (tfit_crc_word.c). */
uint32_t tfit_crc32_word(uint32_t crc, uint32_t w);

/* 1 when every one of `rows` rows of r modes, weighted by the amplitude
 * bounds amax[r], sums to at most 2^100 in magnitude (tfit_check.c: the
 * modal family's output bound, the region surfaces' too). */
int tfit_modes_bounded(const float *modes, const float *amax, uint32_t r, uint32_t rows);

/* Far input k of the self-test (tfit_check.c, header-format.md §8): the
 * next three signed 24-bit integers of a linear congruential sequence,
 * times 2^77 (exact), into in; returns the sequence's new state. */
uint32_t tfit_far_input(uint32_t state, float in[3]);

/* Expected coef[] length for the model's family, dims and n_out, or 0 when
 * they are invalid or beyond this build's capacity (tfit_layout.c). */
uint32_t tfit_expected_coefs(const tfit_model *m);

#endif /* TFIT_INTERNAL_H */
