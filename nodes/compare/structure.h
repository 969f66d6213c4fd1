/* structure.h - the structure measure of the `compare` node: the low-frequency part of the
 * relative error over the surfaces that the reference shows smooth, d = G(a - b) / G(b)
 * with G a wide Gaussian (blotches a viewer sees on a flat wall, which RMSE mixes with
 * fine noise). Definition, choices and known values: README.md in this folder.
 *
 * Ownership: the caller owns the input planes and the map; ssg_structure_measure allocates
 * its working planes and frees them before it returns. Thread safety: no shared state; it
 * runs its passes on ssg_parallel_rows, so call it from the node's thread, not inside a
 * row band. Every value is computed by the same operations whatever the thread count, and
 * the sums run in row order in one thread: the same bits on any number of threads. */
#ifndef SSG_COMPARE_STRUCTURE_H
#define SSG_COMPARE_STRUCTURE_H

/* Relative depth jump between 4-neighbours that makes an edge: 5 %, a wall meeting the
   object in front of it (a crease between two walls has no jump, and is left to the
   smoothness test, where its brightness changes). */
#define SSG_STRUCTURE_DEPTH_JUMP 0.05f

struct ssg_structure_input {
    int w, h;                /* size of the planes, px */
    int channels;            /* planes of each image, 1..4; their mean is measured */
    const float *test[4];    /* the image under test, one plane per channel */
    const float *ref[4];     /* the reference */
    const unsigned char *on; /* w * h: 1 = the pixel is compared */
    const float *depth;      /* w * h view depth, or NULL: no depth edges */
    double sigma;            /* the Gaussian's deviation, px (> 0) */
    double smooth;           /* smoothness threshold tau on |G(b) - G2(b)| / G2(b) */
};

struct ssg_structure_result {
    double pp;          /* max d - min d over the measured pixels (NaN: none) */
    double rms;         /* RMS of d - mean(d) over them (NaN: none) */
    long long pixels;   /* how many pixels were measured */
};

/* Fills *r; map (w * h floats, may be NULL) gets d on the measured pixels, 0 elsewhere.
   Returns 0, or -1 when out of memory. */
int ssg_structure_measure(const struct ssg_structure_input *in, float *map,
                          struct ssg_structure_result *r);

#endif
