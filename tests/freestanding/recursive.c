/*
 * recursive.c — a deliberate counter-example for callgraph.c: mutual
 * recursion and a call through a function pointer.  check-freestanding
 * requires the checker to reject it, so the check itself can fail.
 */
int ping(int x);
int pong(int x);
int (*volatile through_pointer)(int) = ping;

int pong(int x)
{
    return x > 0 ? ping(x - 1) + 1 : 0;
}

int ping(int x)
{
    return x > 1 ? pong(x - 2) * 2 + through_pointer(0) : x;
}
