/* scene_tables.c - the scene file's entity kinds as parameter tables (parsing,
 * validation, defaults and docs/scenes.md all read them), and the Markdown reference
 * generated from them (`ssgraph docs scenes`). */
#include <stdio.h>

#include "scene/scene_build.h"

#define BIG 1e9

/* ---- parameter tables ---- */

#define VEC3(nm, st, fld, x, y, z, lo, hi, u, h)                                         \
    {.name = nm, SSG_FIELD_VEC3(struct st, fld), .def3 = {x, y, z},                      \
     .min = lo, .max = hi, .unit = u, .help = h}
#define REQ_VEC3(nm, st, fld, u, h)                                                      \
    {.name = nm, SSG_FIELD_VEC3(struct st, fld), .unit = u,                              \
     .help = h, .required = 1}
#define FLOAT(nm, st, fld, d, lo, hi, u, h)                                              \
    {.name = nm, SSG_FIELD_FLOAT(struct st, fld), .def = d,                              \
     .min = lo, .max = hi, .unit = u, .help = h}
#define TEXT(nm, ty, st, fld, req, h)                                                    \
    {.name = nm, SSG_FIELD_##ty(struct st, fld), .help = h, .required = req}
#define MATERIAL(st) TEXT("material", NAME, st, material, 0,                             \
                          "name of a material defined in this file; default: white 0.8")

static const struct ssg_param_desc camera_params[] = {
    VEC3("position", camera_args, position, 0, 0, 5, 0, 0, "scene units", "eye position"),
    VEC3("target", camera_args, target, 0, 0, 0, 0, 0, "scene units", "point looked at"),
    VEC3("up", camera_args, up, 0, 1, 0, 0, 0, NULL, "up direction hint"),
    FLOAT("fov", camera_args, fov, SSG_DEFAULT_FOV_Y, 1, 179, "degrees",
          "vertical field of view"),
    FLOAT("near", camera_args, near_z, SSG_DEFAULT_NEAR, 1e-6, BIG, "scene units",
          "near plane distance"),
    FLOAT("far", camera_args, far_z, SSG_DEFAULT_FAR, 1e-6, BIG, "scene units",
          "far plane distance"),
};
static const struct ssg_param_desc camera_key_params[] = {
    {.name = "time", SSG_FIELD_FLOAT(struct camera_key_args, time), .min = 0, .max = BIG,
     .unit = "seconds", .help = "when the camera is here (frame f is at f / fps)",
     .required = 1},
    REQ_VEC3("position", camera_key_args, position, "scene units", "eye position"),
    REQ_VEC3("target", camera_key_args, target, "scene units", "point looked at"),
    VEC3("up", camera_key_args, up, 0, 1, 0, 0, 0, NULL,
         "up direction hint; default: the camera line's"),
    FLOAT("fov", camera_key_args, fov, SSG_DEFAULT_FOV_Y, 1, 179, "degrees",
          "vertical field of view; default: the camera line's"),
    {.name = "cut", SSG_FIELD_BOOL(struct camera_key_args, cut), .def = 0,
     .help = "the camera jumps to this key at its time (no path from the key before; "
             "history starts afresh in that frame)"},
};
static const struct ssg_param_desc orbit_params[] = {
    VEC3("target", orbit_args, target, 0, 0, 0, 0, 0, "scene units", "point circled and "
         "looked at"),
    FLOAT("radius", orbit_args, radius, 3, 1e-6, BIG, "scene units",
          "horizontal distance from the target"),
    FLOAT("height", orbit_args, height, 0, -BIG, BIG, "scene units",
          "eye height above the target (along up)"),
    FLOAT("period", orbit_args, period, 10, 1e-6, BIG, "seconds", "time of one turn"),
    FLOAT("start", orbit_args, start, 0, -BIG, BIG, "degrees", "angle around up at time "
          "0: 0 puts the eye on the target's +z side, 90 on its +x side (up = +y); the "
          "angle grows with time"),
    VEC3("up", orbit_args, up, 0, 1, 0, 0, 0, NULL, "the axis circled about, and the "
         "camera's up"),
    FLOAT("fov", orbit_args, fov, SSG_DEFAULT_FOV_Y, 1, 179, "degrees",
          "vertical field of view; default: the camera line's"),
};
static const struct ssg_param_desc frame_rate_params[] = {
    FLOAT("fps", frame_rate_args, fps, 30, 1e-3, 1e4, "frames/s",
          "frames per second: frame f of a run is at time f / fps"),
};
static const char *const alpha_mode_choices[] = {"opaque", "mask", "blend", NULL};
static const struct ssg_param_desc material_params[] = {
    VEC3("albedo", material_args, albedo, 0.8f, 0.8f, 0.8f, 0, 1, NULL,
         "diffuse reflectance, linear RGB (multiplies the texture)"),
    VEC3("specular", material_args, specular, 0, 0, 0, 0, 1, NULL,
         "Blinn-Phong specular colour, linear RGB"),
    FLOAT("shininess", material_args, shininess, 32, 0, 1e4, NULL, "Blinn-Phong exponent"),
    TEXT(
        "texture", STRING, material_args, texture, 0,
        "albedo texture (PNG, JPEG, EXR...; sRGB files are linearised), relative to the scene; "
        "its alpha channel, if any, is the coverage of alpha_mode=mask"),
    {.name = "alpha_mode", SSG_FIELD_ENUM(struct material_args, alpha_mode), .def = 0,
     .choices = alpha_mode_choices,
     .help = "opaque: a surface everywhere; mask: a surface only where opacity x the "
             "texture's alpha >= alpha_cutoff (leaves, fences), to the camera, the lights "
             "and the references alike; blend: read as mask at cutoff 0.5, with a warning "
             "(no pass of ssgraph blends)"},
    FLOAT("alpha_cutoff", material_args, alpha_cutoff, 0.5f, 0, 1, NULL,
          "alpha_mode=mask: the coverage at and above which there is a surface"),
    FLOAT("opacity", material_args, opacity, 1, 0, 1, NULL,
          "multiplies the texture's alpha (glTF's baseColorFactor alpha, OBJ's d)"),
    TEXT("normal_map", STRING, material_args, normal_map, 0,
         "tangent-space normal map (PNG or EXR, read as data, not sRGB: rgb = (n + 1) / 2 "
         "with x along the texture's u, y along v, z the surface normal, as glTF's), on the "
         "shape's or mesh's uvs; relative to the scene"),
    FLOAT("normal_scale", material_args, normal_scale, 1, 0, 100, NULL,
          "multiplies the normal map's x and y (glTF's normalTexture.scale)"),
    VEC3("emission", material_args, emission, 0, 0, 0, 0, BIG, "W/(m^2 sr)",
         "emitted radiance, linear RGB, from both faces: seen directly (gbuffer.emission, "
         "which combine adds), the source of a bounce in reference_gi and of the "
         "screen-space near field where a pipeline feeds it in (docs/scenes.md)"),
};
static const struct ssg_param_desc point_light_params[] = {
    REQ_VEC3("position", light_args, position, "scene units", "light position"),
    VEC3("color", light_args, color, 1, 1, 1, 0, BIG, NULL, "linear RGB"),
    FLOAT("intensity", light_args, intensity, 1, 0, BIG, "W/sr",
          "radiant intensity; irradiance falls off as 1/d^2"),
};
static const struct ssg_param_desc directional_light_params[] = {
    REQ_VEC3("direction", light_args, direction, NULL, "direction the light travels"),
    VEC3("color", light_args, color, 1, 1, 1, 0, BIG, NULL, "linear RGB"),
    FLOAT("intensity", light_args, intensity, 1, 0, BIG, "W/m^2",
          "irradiance on a surface facing the light"),
};
static const struct ssg_param_desc spot_light_params[] = {
    REQ_VEC3("position", light_args, position, "scene units", "light position"),
    REQ_VEC3("direction", light_args, direction, NULL, "the cone's axis: where the light "
             "points"),
    FLOAT("inner_angle", light_args, inner_angle, 20, 0, 89, "degrees",
          "half-angle of the cone of full intensity"),
    FLOAT("outer_angle", light_args, outer_angle, 30, 0.01, 89, "degrees",
          "half-angle beyond which nothing is lit; between the two the intensity falls as "
          "t^2, t = (cos a - cos outer) / (cos inner - cos outer) (glTF's spot)"),
    VEC3("color", light_args, color, 1, 1, 1, 0, BIG, NULL, "linear RGB"),
    FLOAT("intensity", light_args, intensity, 1, 0, BIG, "W/sr",
          "radiant intensity on the axis; irradiance falls off as 1/d^2"),
};
static const struct ssg_param_desc environment_params[] = {
    VEC3("color", environment_args, color, 1, 1, 1, 0, BIG, NULL,
         "constant radiance, linear RGB"),
    FLOAT("intensity", environment_args, intensity, 1, 0, BIG, NULL,
          "multiplies color and image"),
    TEXT("image", STRING, environment_args, image, 0,
         "lat-long HDR image (multiplied by color), relative to the scene"),
};
static const struct ssg_param_desc plane_params[] = {
    MATERIAL(shape_args),
    VEC3("center", shape_args, center, 0, 0, 0, 0, 0, "scene units", "centre of the rectangle"),
    VEC3("size", shape_args, size, 1, 1, 1, 0, BIG, "scene units",
         "[width, unused, depth]: extents along the plane's x and z axes (its y is the "
         "normal)"),
    VEC3("normal", shape_args, normal, 0, 1, 0, 0, 0, NULL,
         "facing direction; the plane's frame is the shortest rotation of +y onto it"),
};
static const struct ssg_param_desc box_params[] = {
    MATERIAL(shape_args),
    VEC3("center", shape_args, center, 0, 0, 0, 0, 0, "scene units", "centre of the box"),
    VEC3("size", shape_args, size, 1, 1, 1, 1e-6, BIG, "scene units", "extents along x, y, z"),
    VEC3("rotate", shape_args, rotate, 0, 0, 0, 0, 0, "degrees",
         "rotation about the centre: about x, then y, then z (world axes)"),
};
static const struct ssg_param_desc sphere_params[] = {
    MATERIAL(shape_args),
    VEC3("center", shape_args, center, 0, 0, 0, 0, 0, "scene units", "centre of the sphere"),
    FLOAT("radius", shape_args, radius, 1, 1e-6, BIG, "scene units", "radius"),
    {.name = "subdivisions", SSG_FIELD_INT(struct shape_args, subdivisions), .def = 32,
     .min = 3, .max = 1024, .help = "latitude bands (twice as many longitude segments)"},
};
static const struct ssg_param_desc mesh_params[] = {
    TEXT("file", STRING, mesh_args, file, 1, "model file, relative to the scene: glTF 2.0 "
         "(.gltf, .glb), or through Assimp OBJ, PLY, FBX, 3DS, STL, DAE, glTF 1.0 and more"),
    TEXT("material", NAME, mesh_args, material, 0,
         "material overriding the file's own; default: the file's materials (diffuse "
         "colour and texture)"),
    VEC3("translate", mesh_args, translate, 0, 0, 0, 0, 0, "scene units", "moves the mesh"),
    VEC3("rotate", mesh_args, rotate, 0, 0, 0, 0, 0, "degrees",
         "about x, then y, then z (world axes), before translate"),
    VEC3("scale", mesh_args, scale, 1, 1, 1, 1e-6, BIG, NULL, "scale factors, applied first "
         "(0.001 for a model in millimetres; `ssgraph check` suggests one)"),
    {.name = "lights", SSG_FIELD_BOOL(struct mesh_args, lights), .def = 1,
     .help = "true: the file's own lights (glTF KHR_lights_punctual point, spot and "
             "directional lights, placed by the mesh line's transform) join the scene's light lines; "
             "false: they are dropped (write your own lines to override them). A lights "
             "file (--lights) replaces them too"},
};

#define KIND(nm, params, args, text) {nm, SSG_TABLE(params), sizeof(struct args), text}

const struct scene_kind_desc ssg_scene_kinds[SK_COUNT] = {
    [SK_CAMERA] = KIND("camera", camera_params, camera_args,
                       "The view: a pinhole camera looking from `position` at `target`. At most "
                       "one; without it a glTF mesh's own camera is used, else the defaults."),
    [SK_CAMERA_KEY] = KIND("camera_key", camera_key_params, camera_key_args,
                           "One key of a camera path (docs/time.md): where the camera is "
                           "at `time`. Two or more keys, in any order in the file, make a "
                           "path that `run --frames N` follows: centripetal Catmull-Rom "
                           "through the positions and, apart, the targets (end keys "
                           "duplicated), up and fov linear; before the first key and after "
                           "the last the camera stays there. `near` and `far` are the "
                           "`camera` line's. The path replaces the `camera` line's view (and "
                           "a glTF camera) from frame 0 on. Static geometry and lights "
                           "only: nothing else moves."),
    [SK_ORBIT] = KIND("orbit", orbit_params, orbit_args,
                      "A camera path that circles `target` at `radius`, `height` above "
                      "it, one turn per `period` seconds, looking at it (docs/time.md). At "
                      "most one, and not beside camera_key lines."),
    [SK_FRAME_RATE] = KIND("frame_rate", frame_rate_params, frame_rate_args,
                           "Frames per second of the sequence (30 without this line): "
                           "frame f is at time f / fps. At most one."),
    [SK_MATERIAL] = KIND("material", material_params, material_args,
                         "A named surface (`clay = material(...)`): Lambert albedo, optionally "
                         "textured, plus a Blinn-Phong highlight in the direct light. Shapes "
                         "and meshes name it with `material=clay`, from anywhere in the file. "
                         "With `alpha_mode=mask` it is a surface only where `opacity` x the "
                         "texture's alpha reaches `alpha_cutoff` (a leaf, a fence): the "
                         "camera, every light's map and the reference nodes' rays all see "
                         "through the rest (tests/fixtures/alpha_mask.scene)."),
    [SK_POINT_LIGHT] = KIND("point_light", point_light_params, light_args,
                            "An isotropic point light. Any number of lights of either kind."),
    [SK_DIRECTIONAL_LIGHT] = KIND("directional_light", directional_light_params, light_args,
                                  "A light at infinity (the sun): parallel rays, no falloff."),
    [SK_SPOT_LIGHT] = KIND("spot_light", spot_light_params, light_args,
                           "A point light lit only within a cone around `direction`: full "
                           "intensity inside `inner_angle`, none beyond `outer_angle`. Its "
                           "map is one perspective face along the axis when outer_angle <= "
                           "60 degrees, else a point light's six cube faces."),
    [SK_ENVIRONMENT] = KIND("environment", environment_params, environment_args,
                            "Light from every direction: a constant sky colour, or a 2:1 "
                            "lat-long HDR probe (centre looking down -z, top row straight "
                            "up); a probe holding NaN or infinity is refused with its pixel. "
                            "At most one."),
    [SK_PLANE] = KIND("plane", plane_params, shape_args,
                      "A one-sided rectangle (two triangles), facing `normal`."),
    [SK_BOX] = KIND("box", box_params, shape_args, "A box of 12 triangles."),
    [SK_SPHERE] = KIND("sphere", sphere_params, shape_args,
                       "A UV sphere of `subdivisions` latitude bands."),
    [SK_MESH] = KIND("mesh", mesh_params, mesh_args,
                     "Triangles from a model file (`mesh(\"bunny.gltf\")`: the file is the "
                     "first positional argument). glTF 2.0 keeps its node transforms, "
                     "baseColorFactor and baseColorTexture; other formats go through Assimp "
                     "(their diffuse colour and texture become the albedo). Transforms apply "
                     "scale, then rotate, then translate. Up axes: glTF, 3DS and DAE arrive "
                     "Y-up (Assimp turns 3DS and DAE: no rotate; a 3DS made Y-up comes out on "
                     "its side and takes `rotate=[90, 0, 0]`); OBJ, PLY, STL and FBX keep "
                     "the file's axes, so a Z-up one takes `rotate=[-90, 0, 0]`; `ssgraph "
                     "check MODEL` says which, and prints a scene around it. Assimp reads in "
                     "a child process: XML or braces nested over 256 deep, and PLY, STL or 3DS "
                     "counts beyond the file's size, are refused before it reads; an import "
                     "that crashes, or runs over `$SSGRAPH_MODEL_TIMEOUT` seconds (default 60, "
                     "plus 1 per 4 MiB of file) or `$SSGRAPH_MODEL_MEMORY` MiB (default half "
                     "the RAM; not under AddressSanitizer), is an error at the mesh line."),
};

/* What a model file's materials and extras become (docs/scenes.md's feature table): one
   row a feature, as honoured now; issue 45 fills in the rows still marked "not read". */
static const struct {
    const char *feature, *gltf, *assimp, *paths, *test;
} model_features[] = {
    {"base colour", "baseColorFactor x baseColorTexture (sRGB, the TEXCOORD_n it names)",
     "diffuse colour x diffuse texture (map_Kd)", "every path", "test_gltf, test_scene"},
    {"alpha mask", "alphaMode MASK: a surface where baseColorFactor alpha x the texture's "
     "alpha >= alphaCutoff", "map_d naming the map_Kd file itself (its alpha channel), "
     "cutoff 0.5", "the G-buffer (CPU rays, GL raster), shadowmaps and lightmaps (CPU and GL), "
     "every Embree ray (reference_ao, reference_gi); not rsm's coarse distance field",
     "test_alpha_mask, test_shadowmaps, test_gltf, test_scene, test_scene_models"},
    {"alpha blend", "alphaMode BLEND: drawn as MASK at cutoff 0.5, with a warning", "-",
     "as alpha mask", "test_gltf, test_scene"},
    {"double-sided", "not read: every surface has two faces on every path", "the same", "-",
     "-"},
    {"a separate opacity texture", "-", "map_d naming another file: its alpha channel, "
     "else its first, is the mask (cutoff 0.5), resampled onto the diffuse texture (or a "
     "white one)", "as alpha mask", "test_scene_models"},
    {"scalar opacity", "-", "not read (d, Tr below 1: drawn opaque)", "-", "-"},
    {"normal maps", "normalTexture (tangent space) and its scale, on the base colour's "
     "texture coordinates; the file's TANGENT, else tangents made per vertex from the uvs "
     "(Lengyel 2001)", "norm (map_bump, a height map, is not read)", "every shading normal: the G-buffer (CPU, "
     "GL), lightmaps' normals (CPU, GL), reference_gi's bounce hits; a scene file's material "
     "takes one as normal_map (PNG or EXR)", "test_normal_map, test_scene_models"},
    {"emission", "emissiveFactor x KHR_materials_emissive_strength, x emissiveTexture (sRGB, "
     "on the material's texture coordinates)", "Ke x map_Ke (sRGB; Ke black or absent: "
     "1)", "gbuffer.emission "
     "(CPU, GL), which combine adds to the frame; reference_gi (seen directly, and as the "
     "source of its one bounce); gi.graph's SSDO near field bounces it within its radius; "
     "no light map or shadow map holds it (in real time an emitter lights only its near "
     "field)",
     "test_emission, test_scene_models"},
    {"vertex colours", "COLOR_0 (VEC3 or VEC4, its alpha not read, linear) multiplies the "
     "base colour", "the first colour set (PLY, OBJ, FBX...), read as sRGB, alpha not read",
     "every albedo: the G-buffer (CPU, GL), lightmaps (CPU, GL), reference_gi's bounce hits",
     "test_vertex_colors, test_scene_models"},
    {"texture transform", "KHR_texture_transform (offset, rotation, scale, texCoord) baked "
     "into the mesh's uvs; a material whose textures' transforms differ keeps the base "
     "colour's (listed as not read)", "-", "every texture lookup, CPU and GL", "test_gltf"},
    {"lights", "KHR_lights_punctual point, spot and directional lights (candela and lux "
     "read as W/sr and W/m^2, a spot's cone as spot_light's); `range` not read", "not read",
     "every path, as "
     "the scene's own lights; the mesh line's lights=false drops them, a lights file "
     "replaces them", "test_gltf_lights"},
    {"camera", "the default scene's first perspective camera", "not read", "the scene's "
     "camera when it has no camera line", "test_gltf"},
    {"dense meshes", "a mesh of 4096 triangles or more, not alpha-masked, is drawn into the "
     "shadow and light maps as its meshoptimizer proxy, within about a quarter of a shadow "
     "map's texel and a sixteenth of a light map's (core/scene/proxy.h; the nodes' "
     "proxy=false draws every triangle)", "the same",
     "shadowmaps and lightmaps (CPU, GL); every other path reads every triangle",
     "test_proxy"},
};

static void model_features_markdown(FILE *stream)
{
    fprintf(stream, "## Model file features\n\nWhat a `mesh` file's materials and extras "
                    "become: glTF 2.0 through tinygltf, the other formats through Assimp. "
                    "A material's alpha (`alpha_mode`, `alpha_cutoff`, `opacity` above) "
                    "means the same from a scene file and from a model.\n\n"
                    "| feature | glTF 2.0 | Assimp (OBJ/MTL, FBX, ...) | honoured by | "
                    "tests |\n|---|---|---|---|---|\n");
    for (size_t i = 0; i < sizeof model_features / sizeof model_features[0]; i++)
        fprintf(stream, "| %s | %s | %s | %s | %s |\n", model_features[i].feature,
                model_features[i].gltf, model_features[i].assimp, model_features[i].paths,
                model_features[i].test);
}

void ssg_scenes_markdown(FILE *stream)
{
    if (!stream)
        return;
    fprintf(stream, "# Scene reference\n\nGenerated by `ssgraph docs scenes` from the "
                    "parameter tables in `core/scene/scene_tables.c`; do not edit by hand. "
                    "[graphs.md](graphs.md) describes the syntax (one entity a line, "
                    "`name = kind(...)`, `set name.arg = value`, comments with `#`); "
                    "relative paths resolve against the scene file; `ssgraph check "
                    "FILE.scene` validates a scene and loads its meshes.\n\n"
                    "`include \"other.scene\"` (relative to the including file) adds "
                    "another scene's entities as if written there, its paths still "
                    "resolved against its own folder; the including file's own `camera`, "
                    "camera path (`camera_key` lines or an `orbit`), `environment` and "
                    "`frame_rate` replace the included ones, so a file of an include and "
                    "camera_key lines is that scene flown along a new path (what the "
                    "viewer's *save path* writes, docs/viewer.md). Includes nest up to 16 "
                    "deep.\n\n"
                    "Entities: ");
    for (int k = 0; k < SK_COUNT; k++)
        fprintf(stream, "%s[`%s`](#%s)", k ? ", " : "", ssg_scene_kinds[k].name,
                ssg_scene_kinds[k].name);
    fprintf(stream, ".\n\n");
    for (int k = 0; k < SK_COUNT; k++) {
        const struct scene_kind_desc *d = &ssg_scene_kinds[k];
        fprintf(stream, "## %s\n\n%s\n\n| name | type | default | accepts | description "
                        "|\n|---|---|---|---|---|\n", d->name, d->doc);
        for (int p = 0; p < d->table.count; p++)
            ssg_param_markdown(&d->table.params[p], stream);
        fprintf(stream, "\n");
    }
    model_features_markdown(stream);
}
