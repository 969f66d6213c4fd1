/* test_distance.c - the scene's coarse distance field (core/scene/distance.h) on a tiny known
 * scene: one square of side 2 on the plane y = 0, 8 voxels on its longest axis, so the voxel
 * side is 0.25 and the grid (2 empty voxels of margin a side) is 12 x 5 x 12 from
 * (-1.5, -0.5, -1.5). The plane lies on the boundary y = 2 voxels, so voxel rows y = 1
 * and 2 touch it and are occupied, over x and z in [1, 10] (the square's edges on the
 * boundaries 2 and 10 touch voxels 1 and 10); every other voxel holds the distance from
 * its centre to the nearest occupied centre, worked out here by hand. A scene without a
 * triangle has no field. The bricked squares give back every voxel's distance, and the
 * grid's 12 x 5 x 12 voxels lie in 3 x 2 x 6 bricks. */
#include <math.h>

#include "check.h"
#include "scene/distance.h"
#include "scene/scene.h"

static void test_plane(void)
{
    float positions[] = {-1, 0, -1, 1, 0, -1, 1, 0, 1, -1, 0, 1};
    uint32_t indices[] = {0, 1, 2, 0, 2, 3};
    struct ssg_mesh mesh = {.vertex_count = 4, .triangle_count = 2, .positions = positions,
                            .indices = indices};
    struct ssg_distance *f = NULL;
    CHECK_EQ(ssg_distance_build(&mesh, 1, 8, &f), SSG_OK);
    if (!f)
        return;
    CHECK_EQ(f->n[0], 12);
    CHECK_EQ(f->n[1], 5);
    CHECK_EQ(f->n[2], 12);
    CHECK(f->voxel == 0.25f);
    CHECK(f->lo[0] == -1.5f && f->lo[1] == -0.5f && f->lo[2] == -1.5f);
    for (int z = 0; z < 12; z++)
        for (int x = 0; x < 12; x++) {
            int inside = x >= 1 && x <= 10 && z >= 1 && z <= 10;
            CHECK_EQ(ssg_distance_at(f, x, 1, z) == 0.0f, inside);
            CHECK_EQ(ssg_distance_at(f, x, 2, z) == 0.0f, inside);
        }
    CHECK(ssg_distance_at(f, 5, 0, 5) == 1.0f);          /* below row 1 */
    CHECK(ssg_distance_at(f, 5, 4, 5) == 2.0f);          /* two above row 2 */
    CHECK(ssg_distance_at(f, 0, 2, 5) == 1.0f);          /* beside the edge x = 1 */
    CHECK(ssg_distance_at(f, 0, 4, 0) == sqrtf(6.0f));   /* (1, 2, 1): 1, 2, 1 away */
    CHECK(ssg_distance_at(f, 11, 3, 11) == sqrtf(3.0f)); /* (10, 2, 10) */
    CHECK(f->bricks[0] == 3 && f->bricks[1] == 2 && f->bricks[2] == 6);
    int wrong = -1;
    if (f->square) {
        wrong = 0;
        for (int z = 0; z < 12; z++)
            for (int y = 0; y < 5; y++)
                for (int x = 0; x < 12; x++)
                    wrong += f->root[f->square[ssg_distance_brick_at(f, x, y, z)]] !=
                             ssg_distance_at(f, x, y, z);
    }
    CHECK_EQ(wrong, 0);
    CHECK(f->square && f->square[ssg_distance_brick_at(f, 0, 4, 0)] == 6); /* sqrt(6) */
    ssg_distance_destroy(&f);
    CHECK(f == NULL);
}

static void test_empty(void)
{
    struct ssg_mesh mesh = {0};
    struct ssg_distance *f = (struct ssg_distance *)&mesh; /* must be overwritten */
    CHECK_EQ(ssg_distance_build(&mesh, 1, 64, &f), SSG_OK);
    CHECK(f == NULL);
    CHECK_EQ(ssg_distance_build(NULL, 0, 64, &f), SSG_OK);
    CHECK(f == NULL);
}

int main(void)
{
    test_plane();
    test_empty();
    return check_report();
}
