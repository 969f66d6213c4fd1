/* stream_store.h - copies a kernel's finished row segment (scratch in L1) into an output
 * plane with streaming (non-temporal) stores. A frame's planes are far larger than the
 * caches, so ordinary stores first fetch each line only to overwrite it; streaming ones
 * skip that read. Measured: gbuffer 10 % faster at 720p (gbuffer_cpu.c). The caller ends
 * each band with ssg_stream_fence() so the stores are visible before the band counts as
 * done. Header-only; thread-safe (each thread writes its own pixels). */
#ifndef SSG_STREAM_STORE_H
#define SSG_STREAM_STORE_H

#include <stdint.h>
#if defined(__SSE__)
#include <immintrin.h>
#endif

/* n floats of src into dst, streaming from dst's first 16-byte boundary on. */
static inline void ssg_stream_store(float *restrict dst, const float *restrict src, int n)
{
    int i = 0;
#if defined(__SSE__)
    for (; i < n && ((uintptr_t)(dst + i) & 15); i++)
        dst[i] = src[i];
    for (; i + 4 <= n; i += 4)
        _mm_stream_ps(dst + i, _mm_loadu_ps(src + i));
#endif
    for (; i < n; i++)
        dst[i] = src[i];
}

/* After a band's streaming stores: they are globally visible before the band is done. */
static inline void ssg_stream_fence(void)
{
#if defined(__SSE__)
    _mm_sfence();
#endif
}

#endif
