/* flip.h - FLIP, the perceptual difference of a test image against a reference, for the
 * `compare` node: LDR-FLIP (Andersson, Nilsson, Akenine-Moller, Oskarsson, Astrom,
 * Fairchild, "FLIP: A Difference Evaluator for Alternating Images", HPG 2020) and
 * HDR-FLIP (Andersson, Nilsson, Shirley, Akenine-Moller, "Visualizing Errors in Rendered
 * High Dynamic Range Images", Eurographics 2021 short papers). Method, choices and
 * departures: README.md in this folder.
 *
 * Ownership: the caller owns the input planes and the map; ssg_flip_map allocates its
 * working planes and frees them before it returns. Thread safety: no shared state; it runs
 * its passes on ssg_parallel_rows, so call it from the node's thread, not inside a row
 * band. Every map value is computed by the same operations whatever the band or thread
 * count, so the map's bytes do not depend on the threads. */
#ifndef SSG_FLIP_H
#define SSG_FLIP_H

/* The paper's default observer: a 0.7 m wide 3840-pixel monitor seen from 0.7 m,
   ppd = 0.7 m * (3840 px / 0.7 m) * pi / 180 (HPG 2020's default observer). */
#define SSG_FLIP_DEFAULT_PPD 67.02064327658225
/* Largest ppd accepted: the filter radii grow as 0.14 ppd (a 281-tap kernel here). */
#define SSG_FLIP_MAX_PPD 1000.0

struct ssg_flip_input {
    int w, h;                 /* size of both images and the map, px */
    const float *test[3];     /* linear RGB planes of the image under test; a grey image
                                 passes its one plane three times */
    const float *ref[3];      /* linear RGB planes of the reference */
    const unsigned char *on;  /* w * h: 1 = the pixel is compared. Elsewhere the test
                                 image takes the reference's value (no difference starts
                                 there), and HDR-FLIP's exposures ignore the pixel */
    double ppd;               /* pixels per degree of visual angle, (0, SSG_FLIP_MAX_PPD] */
    int hdr;                  /* 0 = LDR-FLIP of clamp(x, 0, 1); 1 = HDR-FLIP */
};

/* Fills map (w * h floats, row-major) with the per-pixel FLIP error in [0, 1], 0 where
   the images agree. *exposures (may be NULL) gets the number of LDR-FLIP evaluations
   (1 for LDR). Returns 0, or -1 when out of memory (map undefined). */
int ssg_flip_map(const struct ssg_flip_input *in, float *map, int *exposures);

#endif
