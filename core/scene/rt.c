/* rt.c - the Embree 3 wrapper behind rt.h.
 *
 * Coherent batches go through rtcIntersect1M with the coherent flag: Embree regroups the
 * stream into packets itself. Measured for the 1920x1080 bunny frame (primary rays only,
 * one thread, the variants interleaved in one process, best of 6 rounds): rtcIntersect1
 * per ray 330 ms; rtcIntersect8 in 4x2 pixel tiles 109 ms; rtcIntersect1M over row
 * segments of 64 to 256 pixels 104-109 ms (and up to 25% ahead of the 4x2 packets when
 * the machine was loaded); 1M over 8x8 tiles 121 ms; rtcIntersectNp (SoA pointers) about
 * 1.5x slower than 1M; rtcIntersect16 in 4x4 tiles (not native on AVX2) no faster than
 * rtcIntersect8 in separate runs.
 * The scene is built with RTC_SCENE_FLAG_ROBUST so rays through a shared edge (the
 * diagonal of a two-triangle plane at a pixel centre) never slip through; its cost was
 * within the noise of the measurement above. Occlusion batches (ambient occlusion) go as
 * packets of 8 with the incoherent flag; ssg_rt_occluded_rays has the measurement.
 * A mesh whose material is alpha-masked (scene/coverage.h) gets Embree filter functions
 * for both kinds of query: a hit where the mask has no surface is rejected and the ray
 * goes on, so every CPU ray (the G-buffer's, the references', the AO's) sees through it
 * alike. Only masked meshes carry a filter: an opaque scene traces as fast as before. */
#include "scene/rt.h"

#include <embree3/rtcore.h>
#include <stdlib.h>
#include <string.h>

#include "lang/parse.h"
#include "scene/coverage.h"
#include "scene/scene.h"

/* Rays per rtcIntersect1M call; on the stack, 80 bytes each. */
enum { STREAM = 256 };

/* What a masked mesh's filter function reads: the scene's mesh (its uvs and material). */
struct masked_mesh {
    const struct ssg_scene *scene;
    int mesh;
};

struct ssg_rt {
    RTCDevice device;
    RTCScene scene;
    struct masked_mesh *masked; /* per mesh, the filters' user data */
    struct ssg_diags *diags; /* where Embree errors go while building; NULL afterwards */
    int failed;              /* an Embree error was reported */
};

static void on_error(void *user, enum RTCError code, const char *str)
{
    struct ssg_rt *rt = user;
    rt->failed = 1;
    if (rt->diags)
        ssg_diag_at(rt->diags, SSG_E_BACKEND, (struct ssg_loc){0}, "Embree error %d: %s",
                    (int)code, str ? str : "(no message)");
}

/* Rejects the candidate hits of a masked mesh where its mask leaves no surface (valid -1
   = a ray still asking, 0 = rejected; coverage.h). The hits are N-wide structure of arrays
   (Ng x, y, z, u, v, primID, ...): rtcore_ray.h's RTCHitN_u and friends, which are C++
   only, read them at these offsets. */
static void mask_filter(const struct RTCFilterFunctionNArguments *args)
{
    const struct masked_mesh *mm = args->geometryUserPtr;
    const unsigned n = args->N;
    const float *hit = (const float *)args->hit;
    const unsigned *prim = (const unsigned *)args->hit;
    for (unsigned i = 0; i < n; i++) {
        if (args->valid[i] != -1)
            continue;
        float u = hit[3 * n + i], v = hit[4 * n + i];
        int tri = (int)prim[5 * n + i];
        if (!ssg_mesh_covers(mm->scene, mm->mesh, tri, u, v))
            args->valid[i] = 0;
    }
}

/* Copies one mesh into a new Embree triangle geometry attached under the mesh's index.
 * Embree's own buffers are used because it reads vertices with 16-byte loads and wants
 * padding after the last one, which the scene's arrays do not promise. A masked mesh's
 * filter reads the scene's uvs and textures, which live as long as the scene that owns
 * this struct. */
static void attach_mesh(struct ssg_rt *rt, const struct ssg_scene *scene, unsigned id)
{
    const struct ssg_mesh *mesh = &scene->meshes[id];
    RTCGeometry geom = rtcNewGeometry(rt->device, RTC_GEOMETRY_TYPE_TRIANGLE);
    if (!geom)
        return;
    float *v = rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                       3 * sizeof(float), (size_t)mesh->vertex_count);
    unsigned *t = rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                          3 * sizeof(unsigned), (size_t)mesh->triangle_count);
    if (v && t) {
        memcpy(v, mesh->positions, 3 * sizeof(float) * (size_t)mesh->vertex_count);
        memcpy(t, mesh->indices, 3 * sizeof(unsigned) * (size_t)mesh->triangle_count);
        if (ssg_mesh_masked(scene, (int)id)) {
            rt->masked[id] = (struct masked_mesh){scene, (int)id};
            rtcSetGeometryUserData(geom, &rt->masked[id]);
            rtcSetGeometryIntersectFilterFunction(geom, mask_filter);
            rtcSetGeometryOccludedFilterFunction(geom, mask_filter);
        }
        rtcCommitGeometry(geom);
        rtcAttachGeometryByID(rt->scene, geom, id);
    }
    rtcReleaseGeometry(geom);
}

enum ssg_err ssg_rt_build(const struct ssg_scene *scene, struct ssg_rt **out,
                          struct ssg_diags *diags)
{
    *out = NULL;
    struct ssg_rt *rt = calloc(1, sizeof *rt);
    if (rt)
        rt->masked = calloc((size_t)scene->mesh_count + 1, sizeof *rt->masked);
    if (!rt || !rt->masked) {
        free(rt);
        return SSG_E_NOMEM;
    }
    rt->diags = diags;
    rt->device = rtcNewDevice("verbose=0");
    if (!rt->device) {
        ssg_diag_at(diags, SSG_E_BACKEND, (struct ssg_loc){0}, "cannot create the Embree "
                    "device (error %d)", (int)rtcGetDeviceError(NULL));
        free(rt->masked);
        free(rt);
        return SSG_E_BACKEND;
    }
    rtcSetDeviceErrorFunction(rt->device, on_error, rt);
    rt->scene = rtcNewScene(rt->device);
    if (rt->scene) {
        rtcSetSceneFlags(rt->scene, RTC_SCENE_FLAG_ROBUST);
        rtcSetSceneBuildQuality(rt->scene, RTC_BUILD_QUALITY_HIGH);
        for (int i = 0; i < scene->mesh_count; i++)
            if (scene->meshes[i].triangle_count > 0)
                attach_mesh(rt, scene, (unsigned)i);
        rtcCommitScene(rt->scene);
    }
    rt->diags = NULL;
    if (!rt->scene || rt->failed) {
        ssg_rt_destroy(&rt);
        return SSG_E_BACKEND;
    }
    *out = rt;
    return SSG_OK;
}

void ssg_rt_destroy(struct ssg_rt **rt)
{
    if (!rt || !*rt)
        return;
    if ((*rt)->scene)
        rtcReleaseScene((*rt)->scene);
    rtcReleaseDevice((*rt)->device);
    free((*rt)->masked);
    free(*rt);
    *rt = NULL;
}

static void set_hit(struct ssg_hit *hit, float t, float u, float v, unsigned geom,
                    unsigned prim)
{
    int miss = geom == RTC_INVALID_GEOMETRY_ID;
    hit->t = miss ? 0.0f : t;
    hit->u = u;
    hit->v = v;
    hit->mesh = miss ? -1 : (int)geom;
    hit->triangle = miss ? -1 : (int)prim;
}

static struct RTCRay make_ray(const float org[3], const float dir[3], float tnear, float tfar)
{
    struct RTCRay r;
    r.org_x = org[0], r.org_y = org[1], r.org_z = org[2];
    r.dir_x = dir[0], r.dir_y = dir[1], r.dir_z = dir[2];
    r.tnear = tnear, r.tfar = tfar;
    r.time = 0.0f, r.mask = ~0u, r.id = 0, r.flags = 0;
    return r;
}

void ssg_rt_intersect(const struct ssg_rt *rt, const float org[3], const float dir[3],
                      float tnear, float tfar, struct ssg_hit *hit)
{
    struct RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    struct RTCRayHit rh;
    rh.ray = make_ray(org, dir, tnear, tfar);
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(rt->scene, &ctx, &rh);
    set_hit(hit, rh.ray.tfar, rh.hit.u, rh.hit.v, rh.hit.geomID, rh.hit.primID);
}

/* Copies rays [first, first + n) into Embree's ray-hit layout; tnears NULL = r->tnear. */
static void fill_stream(struct RTCRayHit *rh, const struct ssg_rays *r, const float *tnears,
                        int first, int n)
{
    for (int k = 0; k < n; k++) {
        const float org[3] = {r->ox[first + k], r->oy[first + k], r->oz[first + k]};
        const float dir[3] = {r->dx[first + k], r->dy[first + k], r->dz[first + k]};
        float tnear = tnears ? tnears[first + k] : r->tnear;
        rh[k].ray = make_ray(org, dir, tnear, r->tfar);
        rh[k].hit.geomID = RTC_INVALID_GEOMETRY_ID;
        rh[k].hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    }
}

void ssg_rt_intersect_rays_past(const struct ssg_rt *rt, const struct ssg_rays *rays,
                                const float *tnears, struct ssg_hit *hits)
{
    struct RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    ctx.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    struct RTCRayHit rh[STREAM];
    for (int first = 0; first < rays->count; first += STREAM) {
        int n = rays->count - first < STREAM ? rays->count - first : STREAM;
        fill_stream(rh, rays, tnears, first, n);
        rtcIntersect1M(rt->scene, &ctx, rh, (unsigned)n, sizeof rh[0]);
        for (int k = 0; k < n; k++)
            set_hit(&hits[first + k], rh[k].ray.tfar, rh[k].hit.u, rh[k].hit.v,
                    rh[k].hit.geomID, rh[k].hit.primID);
    }
}

void ssg_rt_intersect_rays(const struct ssg_rt *rt, const struct ssg_rays *rays,
                           struct ssg_hit *hits)
{
    ssg_rt_intersect_rays_past(rt, rays, NULL, hits);
}

int ssg_rt_occluded(const struct ssg_rt *rt, const float org[3], const float dir[3],
                    float tnear, float tfar)
{
    struct RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    struct RTCRay r = make_ray(org, dir, tnear, tfar);
    rtcOccluded1(rt->scene, &ctx, &r);
    /* Embree marks an occluded ray by setting tfar to -inf */
    return r.tfar < 0.0f;
}

/* Packets of 8 rays (the AVX2 width) with the incoherent flag: ambient-occlusion rays
 * leave one point over the whole hemisphere, so Embree's packet traversal (the coherent
 * flag) only costs. Measured for reference_ao on the Cornell box, the middle 640x120 of the
 * 640x480 frame at 256 rays each, one thread, the styles interleaved in one process,
 * best of 4 rounds, on this 2-core machine while it was loaded: rtcOccluded8 incoherent
 * 20-22 Mrays/s; rtcOccluded1M over 256-ray streams, incoherent 16-18, coherent 8-16;
 * rtcOccluded8 coherent 10-17; rtcOccluded16 coherent 9-16; rtcOccluded4 coherent 7-13;
 * rtcOccluded1 per ray 10-11. (The coherent styles doubled when the rays of a packet
 * were made neighbours on the hemisphere by a Morton order, and still lost.) Every style
 * gave the same answers. */
int ssg_rt_occluded_rays(const struct ssg_rt *rt, const struct ssg_rays *rays,
                         unsigned char *occluded)
{
    struct RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    ctx.flags = RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT;
    struct RTCRay8 p;
    int valid[8], total = 0;
    for (int first = 0; first < rays->count; first += 8) {
        int n = rays->count - first < 8 ? rays->count - first : 8;
        for (int k = 0; k < 8; k++) {
            int i = first + (k < n ? k : 0); /* idle lanes repeat a valid ray */
            valid[k] = k < n ? -1 : 0;
            p.org_x[k] = rays->ox[i], p.org_y[k] = rays->oy[i], p.org_z[k] = rays->oz[i];
            p.dir_x[k] = rays->dx[i], p.dir_y[k] = rays->dy[i], p.dir_z[k] = rays->dz[i];
            p.tnear[k] = rays->tnear, p.tfar[k] = rays->tfar, p.time[k] = 0.0f;
            p.mask[k] = ~0u, p.id[k] = 0, p.flags[k] = 0;
        }
        rtcOccluded8(valid, rt->scene, &ctx, &p);
        for (int k = 0; k < n; k++) { /* an occluded ray gets tfar = -inf */
            int o = p.tfar[k] < 0.0f;
            total += o;
            if (occluded)
                occluded[first + k] = (unsigned char)o;
        }
    }
    return total;
}
