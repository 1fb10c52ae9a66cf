/* chains.c: call chains of known shape for tests/check_stack_bound.sh, which adds
 * up the frames GCC reports (.su) along the chain each entry must take and
 * compares the sum with firmware/stack_bound.sh's. The volatile arrays give each
 * function a frame of its own size; noinline keeps every call a call. */
#define NOINLINE __attribute__((noinline))

NOINLINE int leaf_small(int x)
{
    volatile int a[8];
    a[x & 7] = x;
    return a[(x + 1) & 7];
}

NOINLINE int leaf_large(int x)
{
    volatile int a[40];
    a[x & 31] = x;
    return a[(x + 3) & 31];
}

NOINLINE int middle(int x)
{
    volatile int b[16];
    b[x & 15] = x;
    return leaf_small(x) + b[(x + 5) & 15];
}

/* leaf_large is reached only through this pointer: an indirect call */
int (*volatile hook)(int) = leaf_large;

NOINLINE int through_pointer(int x)
{
    volatile int c[4];
    c[x & 3] = x;
    return hook(c[(x + 1) & 3]);
}

/* the direct call to middle, and the indirect one to the largest leaf */
int entry_indirect(int x)
{
    volatile int d[2];
    d[x & 1] = x;
    return middle(d[0]) + through_pointer(d[1]);
}

/* a tail call: leaf_large is entered from tail_caller's own frame's caller */
NOINLINE int tail_caller(int x)
{
    return leaf_large(x + 1);
}

int entry_tail(int x)
{
    volatile int e[6];
    e[x % 6] = x;
    return tail_caller(e[1]) + 1;
}

/* two functions that call each other: no bound */
NOINLINE int pong(int x);

NOINLINE int ping(int x)
{
    volatile int v = x;
    return v > 0 ? pong(v - 1) + 1 : 0;
}

NOINLINE int pong(int x)
{
    volatile int v = x;
    return v > 0 ? ping(v - 1) + 2 : 0;
}

int entry_recursive(int x)
{
    return ping(x);
}

/* a frame whose size the argument sets: no bound */
NOINLINE int sized_by_argument(int n)
{
    volatile char buffer[n];
    buffer[0] = (char)n;
    return buffer[0];
}

int entry_dynamic(int n)
{
    return sized_by_argument(n);
}
