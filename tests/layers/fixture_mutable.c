/*
 * fixture_mutable.c — what check_globals.sh must reject: a function's
 * static counter, a file-scope variable and a thread-local one.
 */
int tf_fixture_count(void);

static int total;
_Thread_local int tf_fixture_last;

int tf_fixture_count(void)
{
    static int calls;
    tf_fixture_last = ++calls;
    return total += calls;
}
