// median.glsl - the body of the downsample node's median(v, n): the values v[0 .. n - 1],
// n > 0, sorted in place (insertion sort), then the middle one, or for an even count the
// lower of the two middle ones. Written in the words C and GLSL share, so that one text
// makes the same float operations on both backends: downsample_cpu.c and downsample.glsl
// each include it as the body of their median() (`float *v` in C, `inout float v[]` in
// GLSL).
    for (int i = 1; i < n; i++) {
        float t = v[i];
        int k = i;
        for (; k > 0 && v[k - 1] > t; k--)
            v[k] = v[k - 1];
        v[k] = t;
    }
    return v[(n - 1) / 2];
