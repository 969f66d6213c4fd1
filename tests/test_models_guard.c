/* test_models_guard.c - what stands between a hostile model file and Assimp
 * (core/scene/model.h, issue 28). The pre-checks: XML nested 257 deep is refused at the
 * 257th tag's line and column (256 passes; comments, CDATA, empty tags and quoted '>' open
 * nothing), and so are 257 brackets in JSON (not those inside a string); a COLLADA index
 * list holding a character no integer has, an index or count past INT_MAX, a count beyond
 * the file's size, an accessor whose stride is under its <param>s; a PLY header
 * without end_header, element counts beyond the bytes that follow (ASCII and binary, both
 * byte orders), a list longer than its line or its bytes, a binary STL whose 32-bit size
 * product wraps or does not match, a 3DS chunk or array larger than its parent. The child
 * process: an import that hangs runs out of time, one that aborts is reported with its
 * signal, one that allocates without end runs out of memory at the limit (not under
 * AddressSanitizer, which cannot take an address-space limit), and a model comes back
 * through the pipe intact, as does an import's own error. */
#include <signal.h>
#include <stdint.h>
#include <string.h>
#include <sys/resource.h>
#include <unistd.h>

#include "check.h"
#include "scene/model.h"

#if defined(__SANITIZE_ADDRESS__)
#define ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define ASAN 1
#endif
#endif
#ifndef ASAN
#define ASAN 0
#endif

/* The pre-check of data as a file "m" with extension ext; `at` (or NULL): the
   "m:LINE:COLUMN: " or "m: " the message must start with. */
static void expect_precheck(const char *ext, const char *data, size_t len, enum ssg_err code,
                            const char *at)
{
    char why[512] = "";
    CHECK_EQ(ssg_model_precheck_bytes("m", ext, data, len, why, sizeof why), code);
    if (at && strncmp(why, at, strlen(at))) {
        fprintf(stderr, "message '%s' does not start with '%s'\n", why, at);
        CHECK(0);
    }
}

/* head, n copies of open, n of close, tail: a malloc'd string. */
static char *nested(const char *head, const char *open, const char *close, int n,
                    const char *tail)
{
    size_t len = strlen(head) + (size_t)n * (strlen(open) + strlen(close)) + strlen(tail);
    char *s = malloc(len + 1), *p = s;
    p += sprintf(p, "%s", head);
    for (int i = 0; i < n; i++)
        p += sprintf(p, "%s", open);
    for (int i = 0; i < n; i++)
        p += sprintf(p, "%s", close);
    sprintf(p, "%s", tail);
    return s;
}

static void test_xml(void)
{
    /* <COLLADA> is level 1: 255 nodes reach 256, 256 nodes 257, refused at the last one */
    char *ok = nested("<?xml version=\"1.0\"?>\n<COLLADA>", "<node>", "</node>", 255,
                      "</COLLADA>\n");
    char *deep = nested("<?xml version=\"1.0\"?>\n<COLLADA>", "<node>", "</node>", 256,
                        "</COLLADA>\n");
    char at[64];
    snprintf(at, sizeof at, "m:2:%d: ", (int)strlen("<COLLADA>") + 255 * 6 + 1);
    expect_precheck(".dae", ok, strlen(ok), SSG_OK, NULL);
    expect_precheck(".dae", deep, strlen(deep), SSG_E_GLTF, at);
    expect_precheck(".xml", deep, strlen(deep), SSG_E_GLTF, at); /* by content, any name */
    free(ok);
    free(deep);
    /* COLLADA: a stray character among indices, a count no file of its size holds */
    const char *stray = "<COLLADA>\n<p>0 1 2 3 x 5</p></COLLADA>\n";
    expect_precheck(".dae", stray, strlen(stray), SSG_E_GLTF, "m:2:12: ");
    const char *count = "<COLLADA>\n<float_array id=\"a\" count=\"2000000000\">0 1</float_array>"
                        "</COLLADA>\n";
    expect_precheck(".dae", count, strlen(count), SSG_E_GLTF, "m:2:28: ");
    const char *fine = "<COLLADA><float_array count=\"3\">0.5 -1e3 nan</float_array>"
                       "<vcount>3 4</vcount><p>0 1 2 3 4 +5</p><v>0 -1</v></COLLADA>";
    expect_precheck(".dae", fine, strlen(fine), SSG_OK, NULL);
    /* a primitive without its VERTEX input (read before its inputs: valgrind, fuzzed) */
    const char *novertex = "<COLLADA>\n<mesh><triangles count=\"1\">\n<input xsemantic=\"VERTEX\" "
                           "source=\"#v\"/><p>0 1 2</p></triangles></mesh></COLLADA>";
    expect_precheck(".dae", novertex, strlen(novertex), SSG_E_GLTF, "m:2:7: ");
    const char *vertex = "<COLLADA><mesh><polylist count='1'><input semantic='NORMAL'/>"
                         "<input\tsemantic='VERTEX' source='#v'/><vcount>3</vcount>"
                         "<p>0 1 2</p></polylist><lines/></mesh></COLLADA>";
    expect_precheck(".dae", vertex, strlen(vertex), SSG_OK, NULL);
    /* a data array without its count (a null read in the importer; fuzzed) */
    const char *uncounted = "<COLLADA>\n <float_array id='a' xcount='3'>0 1 2</float_array>"
                            "</COLLADA>";
    expect_precheck(".dae", uncounted, strlen(uncounted), SSG_E_GLTF, "m:2:2: ");
    const char *counted = "<COLLADA><float_array\ncount = \"3\" id='a'>0 1 2</float_array>"
                          "<int_array count='0'/></COLLADA>";
    expect_precheck(".dae", counted, strlen(counted), SSG_OK, NULL);
    char *flat = nested("<a>", "<!-- <b> --><![CDATA[<b>]]><?pi <b>?><b/><c x='>' y=\"<\"/>",
                        "", 300, "</a>");
    expect_precheck(".dae", flat, strlen(flat), SSG_OK, NULL);
    free(flat);
}

/* Every kind of data array the COLLADA pre-check lists (model_check_dae.c, ARRAYS): one
   an <accessor> reads past (tests/fixtures/dae/past_KIND.dae: 3 values of 2, refused at
   the accessor, 6:5), and one without its count (refused at the array). A kind dropped
   from the list fails both. */
static void test_dae_arrays(void)
{
    static const char *const kinds[] = {"float_array", "int_array", "bool_array",
                                        "Name_array", "IDREF_array", "SIDREF_array",
                                        "token_array"};
    for (size_t k = 0; k < sizeof kinds / sizeof kinds[0]; k++) {
        char path[128], at[256], why[512] = "", text[160];
        snprintf(path, sizeof path, "tests/fixtures/dae/past_%s.dae", kinds[k]);
        snprintf(at, sizeof at, "%s:6:5: <accessor> reads past the end of its array 'a'",
                 path);
        CHECK_EQ(ssg_model_precheck(path, why, sizeof why), SSG_E_GLTF);
        if (strncmp(why, at, strlen(at))) {
            fprintf(stderr, "%s: '%s' does not start with '%s'\n", kinds[k], why, at);
            CHECK(0);
        }
        snprintf(text, sizeof text, "<COLLADA>\n <%s id='a'>1</%s></COLLADA>", kinds[k],
                 kinds[k]);
        expect_precheck(".dae", text, strlen(text), SSG_E_GLTF, "m:2:2: ");
    }
}

/* An accessor within its array passes (the last value read is the array's last, its
   params may be fewer than its stride); one reading a value past it, by its count, its
   offset or more params than its stride, is refused at the accessor; so are numbers the
   XML reader would wrap or read as hexadecimal, and a negative index in <p>. */
static void test_dae_accessors(void)
{
#define SOURCE(arr, acc) "<COLLADA><source>\n<float_array id='f' count='" arr "'/>\n<accessor " \
                         "source='#f' " acc "><param name='X'/><param/></accessor></source>" \
                         "</COLLADA>"
    const char *const fits[] = {SOURCE("6", "count='3' stride='2'"),
                                SOURCE("7", "count='3' stride='2' offset='1'"),
                                SOURCE("8", "count='2' stride='3' offset='2'"),
                                SOURCE("0", "count='0' stride='2'"), /* reads nothing */
                                SOURCE("6", "count='2' stride='2'")};
    for (size_t i = 0; i < sizeof fits / sizeof fits[0]; i++)
        expect_precheck(".dae", fits[i], strlen(fits[i]), SSG_OK, NULL);
    const char *const past[] = {SOURCE("5", "count='3' stride='2'"),
                                SOURCE("6", "count='3' stride='2' offset='1'"),
                                SOURCE("6", "count='3' stride='1' offset='4'"),
                                SOURCE("2", "count='2'")}; /* stride 1, 2 params */
    for (size_t i = 0; i < sizeof past / sizeof past[0]; i++)
        expect_precheck(".dae", past[i], strlen(past[i]), SSG_E_GLTF, "m:3:1: <accessor>");
    const char *wrapped = SOURCE("6", "count='3' offset='-1'");
    expect_precheck(".dae", wrapped, strlen(wrapped), SSG_E_GLTF, "m:3:41: offset=");
    const char *hex = SOURCE("6", "count='3' stride='0x2'");
    expect_precheck(".dae", hex, strlen(hex), SSG_E_GLTF, "m:3:41: stride=");
    const char *negative = SOURCE("-3", "count='1'");
    expect_precheck(".dae", negative, strlen(negative), SSG_E_GLTF, "m:2:28: count=");
#undef SOURCE
    /* the last array of an id is the one the importer keeps */
    const char *twice = "<COLLADA><float_array id='f' count='9'/>\n<accessor source='#f' "
                        "count='9'/>\n<float_array id='f' count='1'/></COLLADA>";
    expect_precheck(".dae", twice, strlen(twice), SSG_E_GLTF, "m:2:1: ");
    const char *p = "<COLLADA><triangles><input semantic='VERTEX'/>\n<p>0 1 -2</p>"
                    "</triangles></COLLADA>";
    expect_precheck(".dae", p, strlen(p), SSG_E_GLTF, "m:2:8: <p> holds a negative");
    const char *vcount = "<COLLADA>\n<vcount>3 -3</vcount></COLLADA>";
    expect_precheck(".dae", vcount, strlen(vcount), SSG_E_GLTF, "m:2:11: ");
}

/* An index or count past INT_MAX in <p>, <vcount> or <h> is refused at its place (the
   importer's int wraps 4294967298 to 2 and 2^31 to 0: a wrong triangle, no error);
   2147483647 is the pre-check's to pass (the importer's own bound refuses it). */
static void test_dae_huge_indices(void)
{
    static const char *const huge[] = {"2147483648", "4294967295", "4294967296", "4294967298",
                                       "+4294967298", "18446744073709551618",
                                       "000000000000000000000000000004294967298"};
    static const char *const lists[] = {"p", "vcount", "h"};
    for (size_t l = 0; l < sizeof lists / sizeof lists[0]; l++)
        for (size_t i = 0; i <= sizeof huge / sizeof huge[0]; i++) {
            const char *n = i < sizeof huge / sizeof huge[0] ? huge[i] : "2147483647";
            char text[256], at[128];
            snprintf(text, sizeof text, "<COLLADA><triangles><input semantic='VERTEX'/>\n"
                     "<%s>0 1\n %s 2</%s></triangles></COLLADA>", lists[l], n, lists[l]);
            snprintf(at, sizeof at, "m:3:2: <%s> holds %s,", lists[l], n);
            if (i < sizeof huge / sizeof huge[0])
                expect_precheck(".dae", text, strlen(text), SSG_E_GLTF, at);
            else
                expect_precheck(".dae", text, strlen(text), SSG_OK, NULL);
        }
}

/* An accessor whose stride is less than its <param>s (0 included) reads overlapping
   values (stride 0: every vertex the first) and is refused at the accessor; the stride
   a message names is the one written, not a clamped one. */
static void test_dae_strides(void)
{
#define SOURCE(acc) "<COLLADA><source>\n<float_array id='f' count='9'/>\n<accessor " \
                    "source='#f' count='3' " acc "><param name='X'/><param name='Y'/>" \
                    "<param name='Z'/></accessor></source></COLLADA>"
    const char *const fewer[] = {SOURCE("stride='0'"), SOURCE("stride='1'"),
                                 SOURCE("stride='2'"), SOURCE("")}; /* 1 when not given */
    for (size_t i = 0; i < sizeof fewer / sizeof fewer[0]; i++)
        expect_precheck(".dae", fewer[i], strlen(fewer[i]), SSG_E_GLTF,
                        "m:3:1: <accessor> has stride ");
    const char *three = SOURCE("stride='3'");
    expect_precheck(".dae", three, strlen(three), SSG_OK, NULL);
    const char *wide = SOURCE("stride='5000'");
    expect_precheck(".dae", wide, strlen(wide), SSG_E_GLTF,
                    "m:3:1: <accessor> reads past the end of its array 'f': offset 0 + "
                    "(count 3 - 1) x stride 5000 + 5000 values");
    const char *huge = SOURCE("stride='99999999999999999999999'");
    expect_precheck(".dae", huge, strlen(huge), SSG_E_GLTF,
                    "m:3:1: <accessor> reads past the end of its array 'f': offset 0 + "
                    "(count 3 - 1) x stride 99999999999999999999999 + ");
#undef SOURCE
}

static void test_braces(void)
{
    char *deep = nested("{\"a\": ", "[", "]", 256, "}"); /* '{' and 256 '[': 257 levels */
    expect_precheck(".gltf", deep, strlen(deep), SSG_E_GLTF, "m:1:262: ");
    char *text = nested("{\"a\": \"", "{[", "", 300, "\"}"); /* inside a string */
    expect_precheck(".gltf", text, strlen(text), SSG_OK, NULL);
    free(deep);
    free(text);
}

#define PLY_HEAD(format, faces)                                                         \
    "ply\nformat " format " 1.0\nelement vertex 3\nproperty float x\nproperty float y\n" \
    "property float z\nelement face " faces "\nproperty list uchar int vertex_indices\n" \
    "end_header\n"

/* A binary PLY of one triangle (a list count `n`, as a uint list); len into *len. */
static char *binary_ply(int big, const char *faces, uint32_t n, size_t *len)
{
    const char *head = big ? "ply\nformat binary_big_endian 1.0\nelement vertex 3\n"
                             "property float x\nproperty float y\nproperty float z\n"
                             "element face %s\nproperty list uint int vertex_indices\n"
                             "end_header\n"
                           : "ply\nformat binary_little_endian 1.0\nelement vertex 3\n"
                             "property float x\nproperty float y\nproperty float z\n"
                             "element face %s\nproperty list uint int vertex_indices\n"
                             "end_header\n";
    char *s = calloc(1, 1024);
    size_t at = (size_t)sprintf(s, head, faces) + 36; /* three zero vertices */
    for (int k = 0; k < 4; k++) /* the count, then indices 0 1 2 */
        s[at + (size_t)(big ? 3 - k : k)] = (char)(n >> (8 * k));
    at += 4;
    for (int v = 0; v < 3; v++, at += 4)
        s[at + (big ? 3 : 0)] = (char)v;
    *len = at;
    return s;
}

static void test_ply(void)
{
    const char *triangle = PLY_HEAD("ascii", "1") "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
    expect_precheck(".ply", triangle, strlen(triangle), SSG_OK, NULL);
    const char *hang = "ply\nformat ascii 1.0\n"; /* spun forever in Assimp */
    expect_precheck(".ply", hang, strlen(hang), SSG_E_GLTF, "m: ");
    const char *many = PLY_HEAD("ascii", "1000000") "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
    expect_precheck(".ply", many, strlen(many), SSG_E_GLTF, "m:7:14: ");
    const char *list = PLY_HEAD("ascii", "1") "0 0 0\n1 0 0\n0 1 0\n4000000000 0 1 2\n";
    expect_precheck(".ply", list, strlen(list), SSG_E_GLTF, "m:13:1: ");
    const char *unknown = "ply\nformat binary_little_endian 1.0\nelement vertex 3\n"
                          "property uendian x\nelement face 2000000000\n"
                          "property list uchar int vertex_indices\nend_header\n0123456789";
    expect_precheck(".ply", unknown, strlen(unknown), SSG_E_GLTF, "m:5:14: "); /* fuzzed */
    const char *format = "ply\nformat binary_little_enidan 1.0\nelement face 2000000000\n"
                         "property list uchar int vertex_indices\nend_header\n0123456789";
    expect_precheck(".ply", format, strlen(format), SSG_E_GLTF, "m:3:14: "); /* fuzzed too */
    const char *digits = "ply\nformat ascii 1.0\nelement 22222222222face 2\nend_header\n";
    expect_precheck(".ply", digits, strlen(digits), SSG_E_GLTF, "m:3:9: "); /* and this */
    const char *digits18 = PLY_HEAD("ascii", "1") "0 0 0\n1 0 0\n-555555555555555555.5 1 0\n"
                           "3 0 1 2\n";
    expect_precheck(".ply", digits18, strlen(digits18), SSG_E_GLTF, "m:12:1: "); /* fuzzed */
    const char *digits17 = PLY_HEAD("ascii", "1") "0 0 0\n1 0 0\n-55555555555555555.5e-3 1 0\n"
                           "3 0 1 2\n";
    expect_precheck(".ply", digits17, strlen(digits17), SSG_OK, NULL);
    const char *twice = "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n"
                        "element vertex 3\nproperty float x\nend_header\n0\n0\n1\n2\n";
    expect_precheck(".ply", twice, strlen(twice), SSG_E_GLTF, "m:5:9: "); /* valgrind found */
    const char nul[] = "ply\nformat ascii 1.0\ncomment a\0b\nend_header\n"; /* and a hang */
    expect_precheck(".ply", nul, sizeof nul - 1, SSG_E_GLTF, "m:3:10: ");
    const char *hidden = PLY_HEAD("ascii", "1") "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
    char cr[512];
    snprintf(cr, sizeof cr, "%.*s\r%s", (int)(strstr(hidden, "end_header") - hidden), hidden,
             strstr(hidden, "end_header")); /* "\n\rend_header": Assimp never sees it */
    expect_precheck(".ply", cr, strlen(cr), SSG_E_GLTF, "m: ");
    snprintf(cr, sizeof cr, "%.*s\r%s", (int)(strstr(hidden, "\nend_header") - hidden), hidden,
             strstr(hidden, "\nend_header")); /* "\r\nend_header": a CRLF header is fine */
    expect_precheck(".ply", cr, strlen(cr), SSG_OK, NULL);
    const char *negative = PLY_HEAD("ascii", "1") "0 0 0\n1 0 0\n0 1 0\n-1 0 1 2\n";
    expect_precheck(".ply", negative, strlen(negative), SSG_E_GLTF, "m:13:1: ");
    for (int big = 0; big < 2; big++) {
        size_t len;
        char *ply = binary_ply(big, "1", 3, &len);
        expect_precheck(".ply", ply, len, SSG_OK, NULL);
        expect_precheck(".ply", ply, len - 1, SSG_E_GLTF, "m: "); /* the data end early */
        free(ply);
        ply = binary_ply(big, "2000000000", 3, &len); /* the 219-byte bomb */
        expect_precheck(".ply", ply, len, SSG_E_GLTF, "m:7:14: ");
        free(ply);
        ply = binary_ply(big, "1", 4000000000u, &len);
        expect_precheck(".ply", ply, len, SSG_E_GLTF, "m: ");
        free(ply);
    }
}

static void test_stl(void)
{
    char stl[134] = "binary stl";
    stl[80] = 1; /* one facet: 84 + 50 bytes */
    expect_precheck(".stl", stl, 134, SSG_OK, NULL);
    stl[80] = 1, stl[81] = 0, stl[82] = 0, stl[83] = (char)0x80; /* 2^31 + 1: wraps to 134 */
    expect_precheck(".stl", stl, 134, SSG_E_GLTF, "m: ");
    stl[80] = 5, stl[83] = 0;
    expect_precheck(".stl", stl, 134, SSG_E_GLTF, "m: ");
    const char *ascii = "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"
                        "vertex 0 1 0\nendloop\nendfacet\nendsolid t\n";
    expect_precheck(".stl", ascii, strlen(ascii), SSG_OK, NULL);
}

/* A 3DS chunk: id, size (the 6-byte header included), body; returns its length. */
static size_t chunk(char *out, unsigned id, const char *body, size_t len)
{
    size_t size = len + 6;
    unsigned char h[6] = {(unsigned char)id, (unsigned char)(id >> 8), (unsigned char)size,
                          (unsigned char)(size >> 8), (unsigned char)(size >> 16),
                          (unsigned char)(size >> 24)};
    memcpy(out, h, 6);
    memmove(out + 6, body, len);
    return size;
}

/* A 3DS of one object with `points` points in a point chunk of room for `room` of them. */
static size_t make_3ds(char *out, unsigned points, unsigned room)
{
    char a[512] = {0}, b[512];
    size_t n = 2 + 12 * (size_t)room;
    a[0] = (char)points, a[1] = (char)(points >> 8);
    n = chunk(b, 0x4110, a, n);
    n = chunk(a, 0x4100, b, n);
    memcpy(b, "obj", 4);
    memcpy(b + 4, a, n);
    n = chunk(a, 0x4000, b, n + 4);
    n = chunk(b, 0x3D3D, a, n);
    return chunk(out, 0x4D4D, b, n);
}

static void test_3ds(void)
{
    char file[1024];
    size_t len = make_3ds(file, 3, 3);
    expect_precheck(".3ds", file, len, SSG_OK, NULL);
    expect_precheck(".3ds", file, len - 1, SSG_E_GLTF, "m: "); /* main chunk beyond the file */
    len = make_3ds(file, 300, 3);
    expect_precheck(".3ds", file, len, SSG_E_GLTF, "m: ");
}

/* ---- the child process ---- */

static enum ssg_err import_hang(const char *path, struct ssg_gltf **out,
                                struct ssg_model_up *up, char *why, size_t why_len)
{
    for (int i = 0; i < 3600; i++) /* an hour: far past any limit a test sets */
        sleep(1);
    return SSG_OK;
}

static enum ssg_err import_abort(const char *path, struct ssg_gltf **out,
                                 struct ssg_model_up *up, char *why, size_t why_len)
{
    struct rlimit none = {0, 0};
    setrlimit(RLIMIT_CORE, &none); /* no core file for a test */
    raise(SIGABRT);
    return SSG_OK;
}

static enum ssg_err import_hog(const char *path, struct ssg_gltf **out,
                               struct ssg_model_up *up, char *why, size_t why_len)
{
    for (;;) { /* the leak is the point: the child ends with the test */
        char *p = malloc(64 << 20);
        if (!p) {
            snprintf(why, why_len, "%s: out of memory", path);
            return SSG_E_NOMEM;
        }
        memset(p, 1, 64 << 20);
    }
}

static enum ssg_err import_fail(const char *path, struct ssg_gltf **out,
                                struct ssg_model_up *up, char *why, size_t why_len)
{
    snprintf(why, why_len, "%s: no triangles in it", path);
    return SSG_E_GLTF;
}

/* Two meshes (one with normals and uvs, one without), a textured material, a camera. */
static enum ssg_err import_model(const char *path, struct ssg_gltf **out,
                                 struct ssg_model_up *up, char *why, size_t why_len)
{
    *up = (struct ssg_model_up){.axis = 2, .sign = -1, .basis = "a test"};
    if (!out)
        return SSG_OK;
    static const float p[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 7};
    static const uint32_t idx[6] = {0, 1, 2, 2, 1, 3};
    struct ssg_gltf *g = calloc(1, sizeof *g);
    g->meshes = calloc(3, sizeof *g->meshes);
    g->mesh_count = 2;
    g->meshes[0] = (struct ssg_mesh){3, 1, malloc(36), malloc(36), malloc(24), malloc(12), 0, NULL, NULL};
    g->meshes[1] = (struct ssg_mesh){4, 2, malloc(48), NULL, NULL, malloc(24), -1, NULL, NULL};
    memcpy(g->meshes[0].positions, p, 36), memcpy(g->meshes[0].normals, p, 36);
    memcpy(g->meshes[0].uvs, p, 24), memcpy(g->meshes[0].indices, idx, 12);
    memcpy(g->meshes[1].positions, p, 48), memcpy(g->meshes[1].indices, idx, 24);
    g->materials = calloc(1, sizeof *g->materials);
    g->material_count = 1;
    g->materials[0] = (struct ssg_gltf_material){"red", {1, 0, 0, 1}, 0, 0, "red.png",
                                                 SSG_ALPHA_MASK, 0.25f, -1, 1.0f, {0, 0, 0}, -1, "", "", ""};
    g->textures = calloc(2, sizeof *g->textures);
    g->texture_count = 1;
    g->textures[0] = (struct ssg_texture){2, 1, calloc(6, sizeof(float)),
                                          calloc(2, sizeof(float))};
    g->textures[0].rgb[5] = 0.5f;
    g->textures[0].alpha[1] = 0.75f; /* the coverage plane crosses the pipe too */
    g->has_camera = 1;
    g->camera.fov_y = 33;
    *out = g;
    return SSG_OK;
}

static enum ssg_err sandbox(ssg_model_import_fn import, double seconds, long long bytes,
                            struct ssg_gltf **out, struct ssg_model_up *up, char *why)
{
    struct ssg_model_limits limits = {seconds, bytes};
    return ssg_model_sandbox("m.obj", import, &limits, out, up, why, 1024);
}

static void expect_message(const char *why, const char *what)
{
    if (strncmp(why, "m.obj: ", 7) || !strstr(why, what)) {
        fprintf(stderr, "message '%s' lacks 'm.obj: ' or '%s'\n", why, what);
        CHECK(0);
    }
}

static void test_sandbox_failures(void)
{
    struct ssg_gltf *g = NULL;
    struct ssg_model_up up;
    char why[1024];
    CHECK_EQ(sandbox(import_hang, 0.3, 0, &g, &up, why), SSG_E_GLTF);
    expect_message(why, "ran out of time (0.3 s");
    CHECK_EQ(sandbox(import_abort, 30, 0, &g, &up, why), SSG_E_GLTF);
    char signal_text[32];
    snprintf(signal_text, sizeof signal_text, "crashed (signal %d", SIGABRT);
    expect_message(why, signal_text);
    if (!ASAN) {
        CHECK_EQ(sandbox(import_hog, 30, 256 << 20, &g, &up, why), SSG_E_NOMEM);
        expect_message(why, "ran out of memory (limit 256 MiB");
    }
    CHECK_EQ(sandbox(import_fail, 30, 0, &g, &up, why), SSG_E_GLTF);
    expect_message(why, "no triangles in it");
    CHECK(g == NULL);
}

static void test_sandbox_model(void)
{
    struct ssg_gltf *g = NULL;
    struct ssg_model_up up;
    char why[1024];
    CHECK_EQ(sandbox(import_model, 30, 1LL << 30, &g, &up, why), SSG_OK);
    CHECK(up.axis == 2 && up.sign == -1 && !strcmp(up.basis, "a test"));
    CHECK(g && g->mesh_count == 2 && g->material_count == 1 && g->texture_count == 1);
    if (g && g->mesh_count == 2) {
        CHECK(g->meshes[0].normals && g->meshes[0].uvs && !g->meshes[1].normals);
        CHECK_EQ(g->meshes[1].indices[5], 3);
        CHECK_NEAR(g->meshes[1].positions[11], 7, 0);
        CHECK_EQ(g->meshes[1].material, -1);
        CHECK(!strcmp(g->materials[0].texture_file, "red.png"));
        CHECK_NEAR(g->textures[0].rgb[5], 0.5, 0);
        CHECK(g->textures[0].alpha != NULL);
        CHECK_NEAR(g->textures[0].alpha ? g->textures[0].alpha[1] : 0, 0.75, 0);
        CHECK_EQ(g->materials[0].alpha_mode, SSG_ALPHA_MASK);
        CHECK_NEAR(g->materials[0].alpha_cutoff, 0.25, 0);
        CHECK(g->has_camera && g->camera.fov_y == 33);
    }
    ssg_gltf_destroy(&g);
    up.axis = 0;
    CHECK_EQ(sandbox(import_model, 30, 0, NULL, &up, why), SSG_OK); /* the up axis alone */
    CHECK_EQ(up.axis, 2);
}

int main(void)
{
    test_xml();
    test_dae_arrays();
    test_dae_accessors();
    test_dae_huge_indices();
    test_dae_strides();
    test_braces();
    test_ply();
    test_stl();
    test_3ds();
    test_sandbox_failures();
    test_sandbox_model();
    return check_report();
}
