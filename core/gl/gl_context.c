/* gl_context.c - the one place that creates a GL context: OSMesa (software, llvmpipe; what
 * a machine without a GPU and CI use) or EGL on a device (a real GPU, headless). Everything
 * after creation is the same GL 4.5 core code, called through the table of gl_fn.h.
 * OSMesa and EGL are both opened with dlopen, on the first GL node: the binary needs neither
 * when no node runs on GL, and a process that never draws does not pay for loading Mesa
 * and LLVM (about 90 ms of dynamic linking on the development machine). */
/* glcorearb.h before osmesa.h: osmesa.h pulls in the legacy gl.h, which would otherwise
 * hide the GL 1.1 function-pointer types the table needs. */
#include <GL/glcorearb.h>
#include <GL/osmesa.h>

#include <dlfcn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define EGL_NO_X11
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include "gl/gl_fn.h"

struct ssg_gl_fns ssg_gl_fn;

typedef void (*any_fn)(void);
typedef any_fn (*getproc_fn)(const char *name);

/* The four OSMesa entry points ssgraph calls, looked up in libOSMesa.so.8 once. */
static struct {
    void *lib;
    OSMesaContext (*create)(const int *attribs, OSMesaContext share);
    GLboolean (*make_current)(OSMesaContext, void *, GLenum, GLsizei, GLsizei);
    void (*destroy)(OSMesaContext);
    OSMESAproc (*getproc)(const char *name);
} osm;

static struct {
    int platform;          /* 0 = none, 1 = OSMesa, 2 = EGL */
    OSMesaContext osmesa;
    unsigned char osmesa_pixels[4 * 4 * 4]; /* OSMesa needs a colour buffer; we draw to FBOs */
    void *egl_lib;
    EGLDisplay egl_display;
    EGLContext egl_context;
    PFNEGLMAKECURRENTPROC egl_make_current;
    PFNEGLDESTROYCONTEXTPROC egl_destroy_context;
    char renderer[128];
} ctx;

static any_fn osmesa_getproc(const char *name)
{
    return (any_fn)osm.getproc(name);
}

/* dlsym's object pointer to a function pointer: POSIX guarantees the round trip. */
#define OSMESA_SYM(field, name)                                                            \
    do {                                                                                   \
        void *sym = dlsym(osm.lib, name);                                                  \
        memcpy(&osm.field, &sym, sizeof sym);                                              \
        if (!osm.field) {                                                                  \
            snprintf(why, why_len, "libOSMesa.so.8 lacks %s", name);                       \
            return 0;                                                                      \
        }                                                                                  \
    } while (0)

static int osmesa_open(char *why, size_t why_len)
{
    if (osm.lib)
        return 1;
    osm.lib = dlopen("libOSMesa.so.8", RTLD_NOW | RTLD_LOCAL);
    if (!osm.lib) {
        snprintf(why, why_len, "libOSMesa.so.8 not found (%s; Debian: libosmesa6)", dlerror());
        return 0;
    }
    OSMESA_SYM(create, "OSMesaCreateContextAttribs");
    OSMESA_SYM(make_current, "OSMesaMakeCurrent");
    OSMESA_SYM(destroy, "OSMesaDestroyContext");
    OSMESA_SYM(getproc, "OSMesaGetProcAddress");
    return 1;
}

static PFNEGLGETPROCADDRESSPROC egl_getproc_fn;
static any_fn egl_getproc(const char *name)
{
    return (any_fn)egl_getproc_fn(name);
}

static int create_osmesa(char *why, size_t why_len)
{
    const int attribs[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 0,
                           OSMESA_STENCIL_BITS, 0, OSMESA_ACCUM_BITS, 0,
                           OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                           OSMESA_CONTEXT_MAJOR_VERSION, 4, OSMESA_CONTEXT_MINOR_VERSION, 5, 0};
    if (!osmesa_open(why, why_len))
        return 0;
    ctx.osmesa = osm.create(attribs, NULL);
    if (!ctx.osmesa) {
        snprintf(why, why_len, "OSMesa could not create a GL 4.5 core context (is Mesa's "
                 "libosmesa6 with llvmpipe installed?)");
        return 0;
    }
    if (!osm.make_current(ctx.osmesa, ctx.osmesa_pixels, GL_UNSIGNED_BYTE, 4, 4)) {
        snprintf(why, why_len, "OSMesa could not make its context current");
        osm.destroy(ctx.osmesa);
        ctx.osmesa = NULL;
        return 0;
    }
    ctx.platform = 1;
    return 1;
}

/* A device is a GPU when it has a DRM node and is not Mesa's software device. */
static int egl_device_is_gpu(PFNEGLQUERYDEVICESTRINGEXTPROC query, EGLDeviceEXT dev)
{
    const char *ext = query ? query(dev, EGL_EXTENSIONS) : NULL;
    return ext && strstr(ext, "EGL_EXT_device_drm") && !strstr(ext, "EGL_MESA_device_software");
}

#define EGL_LOAD(type, var, name)                                                          \
    type var = (type)(void *)egl_getproc_fn(name);                                         \
    if (!var) {                                                                            \
        snprintf(why, why_len, "EGL lacks %s", name);                                      \
        return 0;                                                                          \
    }

static EGLDeviceEXT egl_pick_device(int want_gpu, char *why, size_t why_len)
{
    EGL_LOAD(PFNEGLQUERYDEVICESEXTPROC, query_devices, "eglQueryDevicesEXT");
    PFNEGLQUERYDEVICESTRINGEXTPROC query_string =
        (PFNEGLQUERYDEVICESTRINGEXTPROC)(void *)egl_getproc_fn("eglQueryDeviceStringEXT");
    EGLDeviceEXT devices[16];
    EGLint count = 0;
    if (!query_devices(16, devices, &count) || count < 1) {
        snprintf(why, why_len, "EGL found no device");
        return NULL;
    }
    for (int i = 0; i < count; i++)
        if (!want_gpu || egl_device_is_gpu(query_string, devices[i]))
            return devices[i];
    snprintf(why, why_len, "EGL found %d device(s), none of them a GPU", count);
    return NULL;
}

static int egl_start(int want_gpu, char *why, size_t why_len)
{
    ctx.egl_lib = dlopen("libEGL.so.1", RTLD_NOW | RTLD_LOCAL);
    if (!ctx.egl_lib) {
        snprintf(why, why_len, "libEGL.so.1 not found (%s)", dlerror());
        return 0;
    }
    egl_getproc_fn = (PFNEGLGETPROCADDRESSPROC)dlsym(ctx.egl_lib, "eglGetProcAddress");
    if (!egl_getproc_fn) {
        snprintf(why, why_len, "libEGL.so.1 has no eglGetProcAddress");
        return 0;
    }
    EGLDeviceEXT dev = egl_pick_device(want_gpu, why, why_len);
    if (!dev)
        return 0;
    EGL_LOAD(PFNEGLGETPLATFORMDISPLAYEXTPROC, get_display, "eglGetPlatformDisplayEXT");
    EGL_LOAD(PFNEGLINITIALIZEPROC, initialize, "eglInitialize");
    EGL_LOAD(PFNEGLBINDAPIPROC, bind_api, "eglBindAPI");
    EGL_LOAD(PFNEGLCREATECONTEXTPROC, create_context, "eglCreateContext");
    EGL_LOAD(PFNEGLMAKECURRENTPROC, make_current, "eglMakeCurrent");
    EGL_LOAD(PFNEGLDESTROYCONTEXTPROC, destroy_context, "eglDestroyContext");
    ctx.egl_make_current = make_current;
    ctx.egl_destroy_context = destroy_context;
    EGLint major, minor;
    ctx.egl_display = get_display(EGL_PLATFORM_DEVICE_EXT, dev, NULL);
    if (!ctx.egl_display || !initialize(ctx.egl_display, &major, &minor)) {
        snprintf(why, why_len, "EGL could not open the device's display");
        return 0;
    }
    const EGLint attribs[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                              EGL_CONTEXT_OPENGL_PROFILE_MASK,
                              EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
    if (!bind_api(EGL_OPENGL_API) ||
        !(ctx.egl_context = create_context(ctx.egl_display, (EGLConfig)0, EGL_NO_CONTEXT,
                                           attribs))) {
        snprintf(why, why_len, "EGL could not create a GL 4.5 core context");
        return 0;
    }
    if (!make_current(ctx.egl_display, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx.egl_context)) {
        snprintf(why, why_len, "EGL could not make a surfaceless context current");
        return 0;
    }
    ctx.platform = 2;
    return 1;
}

static int load_functions(getproc_fn getproc, char *why, size_t why_len)
{
#define X(type, name)                                                                      \
    ssg_gl_fn.name = (type)getproc("gl" #name);                                            \
    if (!ssg_gl_fn.name) {                                                                 \
        snprintf(why, why_len, "the GL driver lacks gl" #name);                            \
        return 0;                                                                          \
    }
#include "gl/gl_funcs.def"
#undef X
    return 1;
}

static int check_version(char *why, size_t why_len)
{
    GLint major = 0, minor = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    glGetIntegerv(GL_MINOR_VERSION, &minor);
    const char *r = (const char *)glGetString(GL_RENDERER);
    snprintf(ctx.renderer, sizeof ctx.renderer, "%s", r ? r : "unknown renderer");
    if (major * 10 + minor < 45) {
        snprintf(why, why_len, "%s gives GL %d.%d, ssgraph needs 4.5 core", ctx.renderer,
                 major, minor);
        return 0;
    }
    return 1;
}

int ssg_gl_context_create(char *why, size_t why_len)
{
    if (ctx.platform)
        return 1;
    const char *want = getenv("SSG_GL_PLATFORM");
    if (!want || !*want)
        want = "auto";
    int ok = 0;
    char egl_why[256] = "";
    if (!strcmp(want, "egl") || !strcmp(want, "auto")) {
        ok = egl_start(!strcmp(want, "auto"), egl_why, sizeof egl_why);
        if (ok &&
            !(ok = load_functions(egl_getproc, why, why_len) && check_version(why, why_len)))
            ssg_gl_context_destroy();
        if (!ok && !strcmp(want, "egl")) {
            snprintf(why, why_len, "SSG_GL_PLATFORM=egl: %s", egl_why[0] ? egl_why : why);
            return 0;
        }
    }
    if (!ok && (!strcmp(want, "osmesa") || !strcmp(want, "auto"))) {
        ok = create_osmesa(why, why_len) && load_functions(osmesa_getproc, why, why_len) &&
             check_version(why, why_len);
        if (!ok)
            ssg_gl_context_destroy();
    } else if (!ok) {
        snprintf(why, why_len, "SSG_GL_PLATFORM is '%s' (expected auto, egl or osmesa)", want);
    }
    return ok;
}

int ssg_gl_context_bind(void)
{
    if (ctx.platform == 1)
        return osm.make_current(ctx.osmesa, ctx.osmesa_pixels, GL_UNSIGNED_BYTE, 4, 4);
    if (ctx.platform == 2)
        return ctx.egl_make_current(ctx.egl_display, EGL_NO_SURFACE, EGL_NO_SURFACE,
                                    ctx.egl_context);
    return 0;
}

const char *ssg_gl_context_platform(void)
{
    return ctx.platform == 1 ? "OSMesa" : ctx.platform == 2 ? "EGL" : "none";
}

const char *ssg_gl_context_renderer(void)
{
    return ctx.renderer;
}

void ssg_gl_context_destroy(void)
{
    if (ctx.osmesa)
        osm.destroy(ctx.osmesa);
    if (ctx.egl_context) {
        ctx.egl_make_current(ctx.egl_display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        ctx.egl_destroy_context(ctx.egl_display, ctx.egl_context);
    }
    /* The display is not terminated and libEGL stays loaded, on purpose: Mesa's EGL keeps a
     * few allocations until exit, and eglTerminate unloads its driver (dlclose), after which
     * LeakSanitizer can no longer name, and so suppress, the library they came from. Both
     * would gain nothing: the process is about to end, and a later eglInitialize of the
     * same display is a no-op. */
    memset(&ctx, 0, sizeof ctx);
    memset(&ssg_gl_fn, 0, sizeof ssg_gl_fn);
}
