/*
 * tick_control.c — the negative control of tick_paths.c: a loop whose
 * length depends on its input, built with the library's instrumentation
 * (-fsanitize-coverage=trace-pc), so that its calls must take different
 * paths.
 */
float tick_control(float x);

float tick_control(float x)
{
    float acc = 0.0f;
    for (int i = 0; i < 50 && acc < x; ++i) {
        acc += 1.0f;
    }
    return acc;
}
