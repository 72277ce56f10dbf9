/*
 * haptic_loop.c — a haptic servo loop around a generated header: at every
 * tick it reads the force the user applies, evaluates the forward model
 * (force -> surface displacements, for the graphics side), takes the
 * displacement of the contact site and evaluates the contact model
 * (displacement -> the force the tissue returns, for the actuator).
 *
 * The header and its models come from haptic_config.h, which the build
 * writes for each header (tests/firmware/haptic_config.sh):
 *   HAPTIC_HEADER             "name.h"
 *   HAPTIC_FORWARD, HAPTIC_FORWARD_M(x)   first forward model and its TFIT_..._x macros
 *   HAPTIC_CONTACT, HAPTIC_CONTACT_M(x)   first contact model (either may be absent)
 *   HAPTIC_FORWARD_PRONY      the forward model is a prony model (a creeping
 *                             body): stepped once per tick with its state
 *   HAPTIC_FORWARD_RESONANT   the forward model is a resonant model (a body
 *                             with inertia): stepped the same way
 *   HAPTIC_FORWARD_CUT        the forward model is a cut model, evaluated at
 *                             the cut progress HAPTIC_CUT_S (default 1: the
 *                             whole incision, the body the contact model of
 *                             a cut scene is fitted to)
 * and which defines TFIT_NAME_IMPLEMENTATION: this file holds the tables.
 *
 * Everything the tick does has a fixed cost (the evaluator's instruction
 * count does not depend on the input), so the budget check below is a
 * compile-time fact, not a measurement.
 */
#include "board.h"
#include "haptic_config.h"
#include "haptic_loop.h"

#include HAPTIC_HEADER

#ifdef HAPTIC_FORWARD
#define FORWARD_CYCLES(s) HAPTIC_FORWARD_M(s)
#define N_POINTS HAPTIC_FORWARD_M(N_OUT)
#else
#define FORWARD_CYCLES(s) 0u
#define N_POINTS 1u
#endif
#ifdef HAPTIC_CONTACT
#define CONTACT_CYCLES(s) HAPTIC_CONTACT_M(s)
#else
#define CONTACT_CYCLES(s) 0u
#endif

#ifdef HAPTIC_CORE_HZ
/* The servo budget, checked by the compiler against the header's estimate. */
#define BUDGET_CYCLES (HAPTIC_CORE_HZ / HAPTIC_SERVO_HZ / 100u * HAPTIC_BUDGET_PERCENT)
_Static_assert(FORWARD_CYCLES(HAPTIC_CYCLES_SUFFIX) + CONTACT_CYCLES(HAPTIC_CYCLES_SUFFIX) <=
                   BUDGET_CYCLES,
               "the models' estimated cycles exceed the servo budget (HAPTIC_SERVO_HZ, "
               "HAPTIC_BUDGET_PERCENT): use a smaller model or a faster servo core");
#endif

/* A stateful forward model's reset and step (prony: a creeping body;
 * resonant: a body with inertia). */
#if defined(HAPTIC_FORWARD_PRONY)
#define HAPTIC_STATE_RESET tfit_prony_reset
#define HAPTIC_STATE_STEP tfit_prony_step
#elif defined(HAPTIC_FORWARD_RESONANT)
#define HAPTIC_STATE_RESET tfit_resonant_reset
#define HAPTIC_STATE_STEP tfit_resonant_step
#endif

#if defined(HAPTIC_FORWARD_CUT) && !defined(HAPTIC_CUT_S)
#define HAPTIC_CUT_S 1.0f
#endif

static float u[3u * N_POINTS];
#ifdef HAPTIC_STATE_STEP
/* the body's state: the force history the model remembers */
static float forward_state[HAPTIC_FORWARD_M(STATE_WORDS)];
#endif
#if defined(HAPTIC_FORWARD) && defined(HAPTIC_CONTACT)
static uint32_t contact_point; /* forward output point at the contact site */
#endif

static void boot(void)
{
#ifdef HAPTIC_FORWARD
    if (tfit_model_check(&HAPTIC_FORWARD) != TFIT_OK) {
        board_fail("haptic: forward model failed its check (damaged flash?)");
    }
#ifdef HAPTIC_STATE_STEP
    (void)HAPTIC_STATE_RESET(&HAPTIC_FORWARD, forward_state); /* at rest, no force */
#endif
#endif
#ifdef HAPTIC_CONTACT
    if (tfit_model_check(&HAPTIC_CONTACT) != TFIT_OK) {
        board_fail("haptic: contact model failed its check (damaged flash?)");
    }
#endif
#if defined(HAPTIC_FORWARD) && defined(HAPTIC_CONTACT)
    /* The contact model's node among the forward model's outputs (point 0
     * when a test header's models do not share a node). */
    for (uint32_t j = 0u; j < HAPTIC_FORWARD.n_out; ++j) {
        if (HAPTIC_FORWARD.node_ids[j] == HAPTIC_CONTACT.node_ids[0]) {
            contact_point = j;
        }
    }
#endif
}

static void tick(void)
{
    float contact_force[3] = {0.0f, 0.0f, 0.0f};
    tfit_status status;
#ifdef HAPTIC_FORWARD
    float force[3];
    board_read_force(force);
#if defined(HAPTIC_STATE_STEP)
    status = HAPTIC_STATE_STEP(&HAPTIC_FORWARD, forward_state, force, u);
#elif defined(HAPTIC_FORWARD_CUT)
    status = tfit_displacements_cut(&HAPTIC_FORWARD, force, HAPTIC_CUT_S, u);
#else
    status = tfit_displacements(&HAPTIC_FORWARD, force, u);
#endif
#ifdef HAPTIC_CONTACT
    (void)tfit_contact_force(&HAPTIC_CONTACT, &u[3u * contact_point], contact_force);
#endif
#else
    float disp[3];
    board_read_position(disp);
    status = tfit_contact_force(&HAPTIC_CONTACT, disp, contact_force);
    u[0] = disp[0];
    u[1] = disp[1];
    u[2] = disp[2];
#endif
    board_publish(u, N_POINTS, contact_force, (int)status);
}

int main(void)
{
    board_init();
    boot();
    while (board_wait_tick()) {
        tick();
    }
    return board_finish();
}
