/* test_scratch.c - a node's working memory (ssg_node_scratch, node.h): the same block comes
 * back while the size fits (no fresh pages from frame to frame), a larger request gets a
 * larger block, every block is 64-byte aligned, a ctx without a slot uses the thread's, and
 * a slot's block is freed by ssg_scratch_free (LeakSanitizer checks the rest in CI).
 * test_cli checks from the outside that a graph whose filter keeps its scratch between
 * frames (ssdo.graph's separable bilateral) gives the one-frame image over three frames. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "graph/node.h"

static int aligned(const void *p)
{
    return ((uintptr_t)p & 63) == 0;
}

static void slot_is_kept(void)
{
    struct ssg_scratch slot = {0};
    struct ssg_node_ctx ctx = {.instance = "n", .scratch = &slot};
    char *a = ssg_node_scratch(&ctx, 1000);
    CHECK(a != NULL && aligned(a));
    memset(a, 7, 1000); /* usable to its size */
    CHECK(ssg_node_scratch(&ctx, 1000) == a); /* the same block again */
    CHECK(ssg_node_scratch(&ctx, 10) == a);   /* smaller: still it */
    CHECK(slot.bytes >= 1000 && slot.bytes % 64 == 0);
    char *b = ssg_node_scratch(&ctx, 1 << 20); /* larger: a new block */
    CHECK(b != NULL && aligned(b) && slot.data == b && slot.bytes >= (1u << 20));
    memset(b, 1, 1 << 20);
    ssg_scratch_free(&slot);
    CHECK(slot.data == NULL && slot.bytes == 0);
    ssg_scratch_free(&slot); /* twice is harmless */
}

static void thread_slot(void)
{
    struct ssg_node_ctx ctx = {.instance = "n"}; /* no slot: the thread's */
    void *a = ssg_node_scratch(&ctx, 4096);
    CHECK(a != NULL && aligned(a));
    CHECK(ssg_node_scratch(&ctx, 4096) == a);
    struct ssg_scratch own = {0};
    struct ssg_node_ctx other = {.instance = "m", .scratch = &own};
    CHECK(ssg_node_scratch(&other, 4096) != a); /* a slot of its own is not the thread's */
    ssg_scratch_free(&own);
}

int main(void)
{
    slot_is_kept();
    thread_slot();
    return check_report();
}
