/* The C ABI from plain C99: version, errors and the error callback, a scene built through the
 * ABI, rendering, passes, statistics, text, presets, crsh against brute on a built-in scene, and
 * sheafWriteImage (formats, channel layouts, errors).
 * Prints every failed check and exits non-zero when there is any. */
#include <sheaf/sheaf.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"

/* ---- Error callback ---- */

static int g_callback_calls = 0;
static SheafError g_callback_last = SHEAF_OK;

static void on_error(void* user, SheafError code, const char* message) {
    int* calls = (int*)user;
    ++*calls;
    g_callback_last = code;
    (void)message;
}

static int g_expected_errors = 0;

/* Checks that `got` is `want`, that the last error agrees and its message contains each of the
 * NULL-terminated parts. */
static void expect_error(SheafError got, SheafError want, const char* what, const char* part1,
                         const char* part2) {
    const char* message = NULL;
    SheafError last = sheafGetLastError(&message);
    ++g_expected_errors;
    CHECK(got == want, "%s: returned %d, expected %d (%s)", what, (int)got, (int)want,
          message ? message : "(null)");
    CHECK(last == got, "%s: sheafGetLastError says %d, the call returned %d", what, (int)last,
          (int)got);
    CHECK(message != NULL && message[0] != '\0', "%s: empty error message", what);
    CHECK(g_callback_last == want, "%s: the callback saw code %d", what, (int)g_callback_last);
    if (message && part1)
        CHECK(strstr(message, part1) != NULL, "%s: '%s' lacks '%s'", what, message, part1);
    if (message && part2)
        CHECK(strstr(message, part2) != NULL, "%s: '%s' lacks '%s'", what, message, part2);
}

/* ---- Scene helpers ---- */

static const float kQuad[] = {-1, 0, -1, 1, 0, -1, 1, 0, 1, -1, 0, 1};
static const uint32_t kQuadIndices[] = {0, 2, 1, 0, 3, 2};

static void scale_translate(float m[12], float s, float tx, float ty, float tz) {
    memset(m, 0, 12 * sizeof(float));
    m[0] = m[5] = m[10] = s;
    m[3] = tx, m[7] = ty, m[11] = tz;
}

static const float kCamPos[3] = {0, 4, 4}, kCamLook[3] = {0, 0, 0}, kCamUp[3] = {0, 1, 0};
static const float kFov = 60.0f;

/* Pixel of a world point for the camera above (vertical fov, top row first). */
static void project(const float p[3], int w, int h, int* px, int* py) {
    float f[3], r[3], u[3], d[3], len;
    int i;
    for (i = 0; i < 3; ++i) f[i] = kCamLook[i] - kCamPos[i];
    len = sqrtf(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
    for (i = 0; i < 3; ++i) f[i] /= len;
    r[0] = f[1] * kCamUp[2] - f[2] * kCamUp[1];
    r[1] = f[2] * kCamUp[0] - f[0] * kCamUp[2];
    r[2] = f[0] * kCamUp[1] - f[1] * kCamUp[0];
    len = sqrtf(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
    for (i = 0; i < 3; ++i) r[i] /= len;
    u[0] = r[1] * f[2] - r[2] * f[1];
    u[1] = r[2] * f[0] - r[0] * f[2];
    u[2] = r[0] * f[1] - r[1] * f[0];
    for (i = 0; i < 3; ++i) d[i] = p[i] - kCamPos[i];
    {
        const float z = d[0] * f[0] + d[1] * f[1] + d[2] * f[2];
        const float t = tanf(kFov * 0.5f * 3.14159265f / 180.0f);
        const float x = (d[0] * r[0] + d[1] * r[1] + d[2] * r[2]) / (z * t * (float)w / (float)h);
        const float y = (d[0] * u[0] + d[1] * u[1] + d[2] * u[2]) / (z * t);
        *px = (int)((x + 1) * 0.5f * (float)w);
        *py = (int)((1 - y) * 0.5f * (float)h);
    }
}

static float luminance(const float* rgba, int w, int x, int y) {
    const float* p = rgba + 4 * ((size_t)y * (size_t)w + (size_t)x);
    return 0.2126f * p[0] + 0.7152f * p[1] + 0.0722f * p[2];
}

/* A ground quad, a smaller quad floating above it (the same mesh twice: instancing), a light
 * straight above and a camera looking down at the shadow. */
static SheafScene build_scene(void) {
    SheafScene scene = NULL;
    SheafMaterialDesc ground, mirror;
    uint32_t quad = 99, m_ground = 99, m_mirror = 99, obj = 99;
    float t[12];
    const float light_pos[3] = {0, 4, 0}, light_color[3] = {1, 1, 1}, bg[3] = {0.05f, 0.05f, 0.1f};

    OK(sheafSceneNew(&scene));
    sheafMaterialDescInit(&ground);
    CHECK(ground.ior > 1.0f && ground.diffuse > 0.0f, "sheafMaterialDescInit: ior %g diffuse %g",
          ground.ior, ground.diffuse);
    ground.color[0] = 0.9f, ground.color[1] = 0.8f, ground.color[2] = 0.7f;
    mirror = ground;
    mirror.mirror = 0.4f;
    OK(sheafSceneAddMaterial(scene, &ground, &m_ground));
    OK(sheafSceneAddMaterial(scene, &mirror, &m_mirror));
    CHECK(m_ground == 0 && m_mirror == 1, "material ids %u %u", m_ground, m_mirror);
    OK(sheafSceneAddMesh(scene, kQuad, 4, kQuadIndices, 2, NULL, &quad));
    CHECK(quad == 0, "mesh id %u", quad);
    scale_translate(t, 6.0f, 0, 0, 0);
    OK(sheafSceneAddObject(scene, quad, m_ground, t, "ground", &obj));
    CHECK(obj == 0, "object id %u", obj);
    scale_translate(t, 0.75f, 0, 1.5f, 0);
    OK(sheafSceneAddObject(scene, quad, m_mirror, t, NULL, &obj));
    CHECK(obj == 1, "object id %u", obj);
    OK(sheafSceneAddPointLight(scene, light_pos, light_color));
    OK(sheafSceneSetCamera(scene, kCamPos, kCamLook, kCamUp, kFov));
    OK(sheafSceneSetBackground(scene, bg));
    return scene;
}

/* ---- Progress ---- */

static int g_progress_calls = 0;
static int cancel_progress(void* user, float done) {
    (void)user;
    (void)done;
    ++g_progress_calls;
    return 0;
}

/* ---- Tests ---- */

static void test_version(void) {
    int major = -1, minor = -1, patch = -1;
    char expect[64];
    sheafGetVersion(&major, &minor, &patch);
    CHECK(major == SHEAF_VERSION_MAJOR && minor == SHEAF_VERSION_MINOR &&
              patch == SHEAF_VERSION_PATCH,
          "version %d.%d.%d", major, minor, patch);
    sprintf(expect, "%d.%d.%d", major, minor, patch);
    CHECK(strcmp(sheafGetVersionString(), expect) == 0, "version string %s",
          sheafGetVersionString());
    CHECK(strcmp(sheafGetVersionString(), SHEAF_VERSION_STRING) == 0, "SHEAF_VERSION_STRING %s",
          SHEAF_VERSION_STRING);
}

static void test_settings(void) {
    SheafRenderer r = NULL;
    char buf[64];
    size_t needed = 0, count = 0;
    const char *key = NULL, *def = NULL, *allowed = NULL, *help = NULL;

    OK(sheafRendererNew(&r));
    OK(sheafRendererGetString(r, "accel", buf, sizeof buf, &needed));
    CHECK(strcmp(buf, "bvh") == 0 && needed == 4, "default accel '%s' needed %u", buf,
          (unsigned)needed);
    OK(sheafRendererSetFloat(r, "ao.distance", 2.5));
    OK(sheafRendererGetString(r, "ao.distance", buf, sizeof buf, NULL));
    CHECK(strcmp(buf, "2.5") == 0, "ao.distance '%s'", buf);
    OK(sheafRendererSetBool(r, "cull.objects", 0));
    OK(sheafRendererGetString(r, "cull.objects", buf, sizeof buf, NULL));
    CHECK(strcmp(buf, "false") == 0, "cull.objects '%s'", buf);
    OK(sheafRendererSetInt(r, "hierarchy.depth", 3));
    OK(sheafRendererUnset(r, "hierarchy.depth"));
    OK(sheafRendererGetString(r, "hierarchy.depth", buf, sizeof buf, NULL));
    CHECK(strcmp(buf, "2") == 0, "hierarchy.depth after unset '%s'", buf);

    expect_error(sheafRendererSetInt(r, "hierarchy.arity", 1), SHEAF_ERROR_INVALID_SETTING,
                 "hierarchy.arity = 1", "hierarchy.arity", "2..64");
    expect_error(sheafRendererSetString(r, "nokey", "1"), SHEAF_ERROR_INVALID_SETTING,
                 "unknown key", "nokey", NULL);
    expect_error(sheafRendererSetString(r, "hash.mode", "bogus"), SHEAF_ERROR_INVALID_SETTING,
                 "hash.mode = bogus", "hash.mode", "none, crsh, hash32, hash192");
    expect_error(sheafRendererGetString(r, "nokey", buf, sizeof buf, NULL),
                 SHEAF_ERROR_INVALID_SETTING, "get unknown key", "nokey", NULL);

    /* Presets: by name from the build tree's presets directory. */
    OK(sheafRendererLoadPreset(r, "rah"));
    OK(sheafRendererGetString(r, "accel", buf, sizeof buf, NULL));
    CHECK(strcmp(buf, "rah") == 0, "accel after preset rah '%s'", buf);
    OK(sheafRendererGetString(r, "sort.mode", buf, sizeof buf, NULL));
    CHECK(strcmp(buf, "none") == 0, "sort.mode after preset rah '%s'", buf);
    expect_error(sheafRendererLoadPreset(r, "nosuch"), SHEAF_ERROR_INVALID_SETTING, "preset nosuch",
                 "nosuch", "crsh");

    OK(sheafGetSettingCount(&count));
    CHECK(count >= 10, "%u settings", (unsigned)count);
    OK(sheafGetSettingInfo(0, &key, &def, &allowed, &help));
    CHECK(key && def && allowed && help && strlen(key) > 0 && strlen(help) > 0, "setting info 0");
    expect_error(sheafGetSettingInfo(count, &key, NULL, NULL, NULL), SHEAF_ERROR_INVALID_ARGUMENT,
                 "setting index out of range", NULL, NULL);
    OK(sheafRendererRelease(r));
}

static void test_null_arguments(void) {
    SheafRenderer r = NULL;
    expect_error(sheafSceneNew(NULL), SHEAF_ERROR_INVALID_ARGUMENT, "sheafSceneNew(NULL)", "out",
                 NULL);
    expect_error(sheafRendererSetString(NULL, "accel", "brute"), SHEAF_ERROR_INVALID_ARGUMENT,
                 "SetString(NULL renderer)", "renderer", NULL);
    OK(sheafRendererNew(&r));
    expect_error(sheafRendererSetString(r, NULL, "brute"), SHEAF_ERROR_INVALID_ARGUMENT,
                 "SetString(NULL key)", "key", NULL);
    expect_error(sheafRender(r, NULL, NULL), SHEAF_ERROR_INVALID_ARGUMENT, "sheafRender(NULL)",
                 NULL, NULL);
    expect_error(sheafSceneCommit(NULL), SHEAF_ERROR_INVALID_ARGUMENT, "commit(NULL)", "scene",
                 NULL);
    expect_error(sheafFrameGetSize(NULL, NULL, NULL), SHEAF_ERROR_INVALID_ARGUMENT, "GetSize(NULL)",
                 "frame", NULL);
    expect_error(sheafFrameRelease(NULL), SHEAF_ERROR_INVALID_ARGUMENT, "FrameRelease(NULL)", NULL,
                 NULL);
    OK(sheafRendererRelease(r));
    {
        const char* message = NULL;
        SheafError e = sheafGetLastError(&message);
        CHECK(e == SHEAF_OK && message && message[0] == '\0', "last error after success: %d '%s'",
              (int)e, message ? message : "(null)");
    }
}

static void test_scene_errors(void) {
    static const float nan_positions[] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    static const uint32_t bad_indices[] = {0, 1, 7};
    float positions[9];
    uint32_t mesh = 0, mat = 0;
    SheafMaterialDesc m;
    SheafScene s = NULL;

    memcpy(positions, nan_positions, sizeof positions);
    positions[4] = (float)NAN;
    sheafMaterialDescInit(&m);

    OK(sheafSceneNew(&s));
    OK(sheafSceneAddMaterial(s, &m, &mat));
    OK(sheafSceneAddMesh(s, positions, 3, kQuadIndices, 1, NULL, &mesh));
    OK(sheafSceneAddObject(s, mesh, mat, NULL, "nan", NULL));
    expect_error(sheafSceneCommit(s), SHEAF_ERROR_SCENE, "NaN vertex", "not finite", NULL);
    OK(sheafSceneRelease(s));

    OK(sheafSceneNew(&s));
    OK(sheafSceneAddMaterial(s, &m, &mat));
    OK(sheafSceneAddMesh(s, nan_positions, 3, bad_indices, 1, NULL, &mesh));
    OK(sheafSceneAddObject(s, mesh, mat, NULL, NULL, NULL));
    expect_error(sheafSceneCommit(s), SHEAF_ERROR_SCENE, "index out of range", "out of range",
                 NULL);
    expect_error(sheafSceneAddObject(s, 5, mat, NULL, NULL, NULL), SHEAF_ERROR_SCENE,
                 "unknown mesh id", "mesh", NULL);
    expect_error(sheafSceneAddObject(s, mesh, 9, NULL, NULL, NULL), SHEAF_ERROR_SCENE,
                 "unknown material id", "material", NULL);
    expect_error(sheafSceneLoadFile(s, "/nonexistent/scene.pov"), SHEAF_ERROR_SCENE, "missing file",
                 "/nonexistent/scene.pov", "no such file");
    expect_error(sheafSceneLoadFile(s, "builtin:nosuch"), SHEAF_ERROR_SCENE, "builtin:nosuch",
                 "nosuch", NULL);
    expect_error(sheafSceneLoadBuiltin(s, "nosuch"), SHEAF_ERROR_SCENE, "LoadBuiltin nosuch",
                 "nosuch", NULL);
    OK(sheafSceneRelease(s));
}

static void test_render_scene(void) {
    const int W = 64, H = 48;
    SheafScene scene = build_scene();
    SheafRenderer r = NULL;
    SheafFrame frame = NULL;
    int w = 0, h = 0, px, py, lx, ly;
    float *rgba, *ids, small[4];
    double sum = 0, shadow_rays = -1, total = -1, brute = -1, value = 0;
    size_t i, differing = 0, count = 0, needed = 0, needed2 = 0;
    const char* key = NULL;
    char* json;
    char tiny[5];
    static const float shadow_point[3] = {0, 0, 0}, lit_point[3] = {2.5f, 0, 0};

    OK(sheafSceneCommit(scene));
    OK(sheafRendererNew(&r));
    OK(sheafRendererSetInt(r, "width", W));
    OK(sheafRendererSetInt(r, "height", H));
    OK(sheafRendererSetString(r, "accel", "crsh"));
    OK(sheafRender(r, scene, &frame));
    if (!frame) {
        CHECK(frame != NULL, "no frame");
        sheafRendererRelease(r);
        sheafSceneRelease(scene);
        return;
    }
    OK(sheafFrameGetSize(frame, &w, &h));
    CHECK(w == W && h == H, "size %dx%d", w, h);

    rgba = (float*)malloc(sizeof(float) * 4 * W * H);
    ids = (float*)malloc(sizeof(float) * W * H);
    OK(sheafFrameGetPass(frame, "combined", rgba, (size_t)4 * W * H));
    OK(sheafFrameGetPass(frame, "object_id", ids, (size_t)W * H));
    for (i = 0; i < (size_t)4 * W * H; ++i) {
        if (i % 4 != 3) sum += rgba[i];
        if (i >= 4 && i % 4 != 3 && rgba[i] != rgba[i % 4]) ++differing;
    }
    CHECK(sum / (3.0 * W * H) > 0, "mean of the image %g", sum / (3.0 * W * H));
    CHECK(differing > 0, "the combined pass is constant");

    project(shadow_point, W, H, &px, &py);
    project(lit_point, W, H, &lx, &ly);
    CHECK(px >= 0 && px < W && py >= 0 && py < H && lx >= 0 && lx < W && ly >= 0 && ly < H,
          "projected pixels (%d,%d) (%d,%d)", px, py, lx, ly);
    if (px >= 0 && px < W && py >= 0 && py < H && lx >= 0 && lx < W && ly >= 0 && ly < H) {
        const float shadow = luminance(rgba, W, px, py), lit = luminance(rgba, W, lx, ly);
        CHECK(ids[py * W + px] == 0.0f && ids[ly * W + lx] == 0.0f,
              "both sample pixels show the ground: ids %g %g", ids[py * W + px], ids[ly * W + lx]);
        CHECK(lit > shadow * 1.5f + 1e-4f, "lit ground %g is not brighter than the shadow %g", lit,
              shadow);
    }

    /* Other passes and buffer checks. */
    {
        float* buf3 = (float*)malloc(sizeof(float) * 3 * W * H);
        OK(sheafFrameGetPass(frame, "normal", buf3, (size_t)3 * W * H));
        OK(sheafFrameGetPass(frame, "albedo", buf3, (size_t)3 * W * H));
        OK(sheafFrameGetPass(frame, "depth", buf3, (size_t)W * H));
        free(buf3);
    }
    expect_error(sheafFrameGetPass(frame, "bogus", small, 4), SHEAF_ERROR_INVALID_ARGUMENT,
                 "unknown pass", "bogus", NULL);
    expect_error(sheafFrameGetPass(frame, "combined", small, 4), SHEAF_ERROR_INVALID_ARGUMENT,
                 "too small buffer", "12288", NULL);
    {
        /* output.passes: the frame keeps the image only; the same image, the others refused
         * with a message that names the setting. */
        SheafFrame only = NULL;
        float* again = (float*)malloc(sizeof(float) * 4 * W * H);
        OK(sheafRendererSetString(r, "output.passes", "combined"));
        OK(sheafRender(r, scene, &only));
        OK(sheafFrameGetPass(only, "combined", again, (size_t)4 * W * H));
        CHECK(memcmp(again, rgba, sizeof(float) * 4 * W * H) == 0,
              "output.passes=combined changed the image");
        expect_error(sheafFrameGetPass(only, "depth", again, (size_t)W * H),
                     SHEAF_ERROR_INVALID_ARGUMENT, "a pass left out", "no 'depth' pass",
                     "output.passes=combined");
        expect_error(sheafFrameSavePass(only, "normal", "sheaf_capi_no_normal.png"),
                     SHEAF_ERROR_INVALID_ARGUMENT, "saving a pass left out", "no 'normal' pass",
                     "output.passes=combined");
        expect_error(sheafRendererSetString(r, "output.passes", "combined,zdepth"),
                     SHEAF_ERROR_INVALID_SETTING, "an unknown pass", "output.passes", "zdepth");
        OK(sheafRendererUnset(r, "output.passes"));
        sheafFrameRelease(only);
        free(again);
    }

    /* Statistics. */
    OK(sheafFrameGetStatCount(frame, &count));
    CHECK(count > 0, "no statistics");
    OK(sheafFrameGetStat(frame, 0, &key, &value));
    CHECK(key != NULL && key[0] != '\0', "stat 0 has no key");
    OK(sheafFrameGetStatByName(frame, "rays.shadow", &shadow_rays));
    OK(sheafFrameGetStatByName(frame, "tests.total", &total));
    OK(sheafFrameGetStatByName(frame, "tests.brute_force", &brute));
    CHECK(shadow_rays > 0, "rays.shadow = %g", shadow_rays);
    CHECK(total > 0, "tests.total = %g", total);
    CHECK(brute >= total, "tests.brute_force %g < tests.total %g", brute, total);
    expect_error(sheafFrameGetStatByName(frame, "no.such.stat", &value),
                 SHEAF_ERROR_INVALID_ARGUMENT, "unknown statistic", "no.such.stat", NULL);

    /* Text, with the two-call size protocol. */
    OK(sheafFrameGetText(frame, "stats.json", NULL, 0, &needed));
    CHECK(needed > 2, "stats.json needs %u bytes", (unsigned)needed);
    json = (char*)malloc(needed);
    OK(sheafFrameGetText(frame, "stats.json", json, needed, &needed2));
    CHECK(needed2 == needed && strlen(json) + 1 == needed, "json length %u, needed %u",
          (unsigned)strlen(json), (unsigned)needed);
    CHECK(json[0] == '{' && strstr(json, "\"rays.shadow\"") != NULL, "json: %.80s", json);
    OK(sheafFrameGetText(frame, "stats.json", tiny, sizeof tiny, &needed2));
    CHECK(strlen(tiny) == 4 && strncmp(tiny, json, 4) == 0 && needed2 == needed,
          "truncated text '%s'", tiny);
    free(json);
    OK(sheafFrameGetText(frame, "settings", NULL, 0, &needed));
    {
        char* settings = (char*)malloc(needed);
        OK(sheafFrameGetText(frame, "settings", settings, needed, NULL));
        CHECK(strstr(settings, "accel=crsh") != NULL && strstr(settings, "width=64") != NULL,
              "settings text: %s", settings);
        free(settings);
    }
    OK(sheafFrameGetText(frame, "stats.table", NULL, 0, &needed));
    CHECK(needed > 1, "empty stats.table");
    expect_error(sheafFrameGetText(frame, "bogus", NULL, 0, &needed), SHEAF_ERROR_INVALID_ARGUMENT,
                 "unknown text", "bogus", NULL);

    /* Images: an unknown extension is an IO error. */
    expect_error(sheafFrameSaveImage(frame, "capi_test_out.bogusext"), SHEAF_ERROR_IO,
                 "unknown image extension", "capi_test_out.bogusext", NULL);

    /* Reference counting. */
    OK(sheafFrameRetain(frame));
    OK(sheafFrameRelease(frame));
    OK(sheafFrameGetSize(frame, &w, &h));
    OK(sheafFrameRelease(frame));

    /* Cancelling from the progress callback. */
    OK(sheafRendererSetProgressCallback(r, cancel_progress, NULL));
    frame = NULL;
    {
        SheafError e = sheafRender(r, scene, &frame);
        if (g_progress_calls > 0) {
            expect_error(e, SHEAF_ERROR_CANCELLED, "cancelled render", "cancelled", NULL);
            CHECK(frame == NULL, "a cancelled render returned a frame");
        } else {
            CHECK(e == SHEAF_OK, "render without progress calls returned %d", (int)e);
            printf("note: the pipeline never called the progress callback\n");
        }
        if (frame) sheafFrameRelease(frame);
    }
    free(rgba);
    free(ids);
    OK(sheafRendererRelease(r));
    OK(sheafSceneRelease(scene));
}

/* crsh and brute must find the same hits: identical images. */
static void test_crsh_matches_brute(void) {
    const int N = 32;
    SheafScene scene = NULL;
    SheafRenderer r = NULL;
    SheafFrame fc = NULL, fb = NULL;
    size_t n_scenes = 0, i;
    const char* name = NULL;
    int found = 0;

    OK(sheafGetBuiltinSceneCount(&n_scenes));
    for (i = 0; i < n_scenes; ++i) {
        OK(sheafGetBuiltinSceneName(i, &name));
        if (name && strcmp(name, "cornell") == 0) found = 1;
    }
    CHECK(found, "no built-in scene 'cornell'");
    CHECK(strlen(sheafGetDefaultSceneName()) > 0, "no default scene");

    OK(sheafSceneNew(&scene));
    OK(sheafSceneLoadBuiltin(scene, "cornell"));
    OK(sheafRendererNew(&r));
    OK(sheafRendererSetInt(r, "width", N));
    OK(sheafRendererSetInt(r, "height", N));
    OK(sheafRendererSetString(r, "accel", "crsh"));
    OK(sheafRender(r, scene, &fc)); /* commits implicitly */
    OK(sheafRendererSetString(r, "accel", "brute"));
    OK(sheafRender(r, scene, &fb));
    if (fc && fb) {
        float* a = (float*)malloc(sizeof(float) * 4 * N * N);
        float* b = (float*)malloc(sizeof(float) * 4 * N * N);
        double brute_tests = 0, crsh_tests = 0;
        OK(sheafFrameGetPass(fc, "combined", a, (size_t)4 * N * N));
        OK(sheafFrameGetPass(fb, "combined", b, (size_t)4 * N * N));
        CHECK(memcmp(a, b, sizeof(float) * 4 * N * N) == 0,
              "crsh and brute images of cornell differ");
        OK(sheafFrameGetStatByName(fc, "tests.total", &crsh_tests));
        OK(sheafFrameGetStatByName(fb, "tests.total", &brute_tests));
        printf("cornell %dx%d: tests.total crsh %.0f, brute %.0f\n", N, N, crsh_tests, brute_tests);
        free(a);
        free(b);
    }
    if (fc) sheafFrameRelease(fc);
    if (fb) sheafFrameRelease(fb);
    OK(sheafRendererRelease(r));
    OK(sheafSceneRelease(scene));
}

/* ---- Regions: parts of a frame saved, read back and put together ---- */

static void test_regions(void) {
    enum { W = 24, H = 18 };
    SheafScene scene = NULL;
    SheafRenderer r = NULL;
    SheafFrame whole = NULL, parts[3] = {NULL, NULL, NULL}, loaded[3] = {NULL, NULL, NULL};
    SheafFrame merged = NULL, bad = NULL, half = NULL;
    const float plain = 0.5f;
    const char* files[3] = {"capi_test_part0.exr", "capi_test_part1.exr", "capi_test_part2.exr"};
    /* Three strips of rows: 0..6, 7..12, 13..17. */
    const int y0[3] = {0, 7, 13}, rows[3] = {7, 6, 5};
    int i, x = -1, y = -1, fw = 0, fh = 0, w = 0, h = 0;
    double parts_stat = 0;

    OK(sheafSceneNew(&scene));
    OK(sheafSceneLoadBuiltin(scene, "office"));
    OK(sheafRendererNew(&r));
    OK(sheafRendererSetInt(r, "width", W));
    OK(sheafRendererSetInt(r, "height", H));
    OK(sheafRendererSetInt(r, "aa.samples", 2));
    OK(sheafRendererSetString(r, "output.exr", "float"));
    OK(sheafRender(r, scene, &whole));
    for (i = 0; i < 3; ++i) {
        OK(sheafRendererSetInt(r, "region.y", y0[i]));
        OK(sheafRendererSetInt(r, "region.height", rows[i]));
        OK(sheafRender(r, scene, &parts[i]));
        if (!parts[i]) continue;
        OK(sheafFrameGetSize(parts[i], &w, &h));
        OK(sheafFrameGetRegion(parts[i], &x, &y, &fw, &fh));
        CHECK(w == W && h == rows[i] && x == 0 && y == y0[i] && fw == W && fh == H,
              "part %d: %dx%d at (%d, %d) of %dx%d", i, w, h, x, y, fw, fh);
        OK(sheafFrameSaveImage(parts[i], files[i]));
        OK(sheafFrameLoadImage(files[i], &loaded[i]));
    }
    /* Out of order: the parts say where they go. */
    {
        SheafFrame order[3];
        order[0] = loaded[2], order[1] = loaded[0], order[2] = loaded[1];
        OK(sheafFrameAssemble(order, 3, &merged));
    }
    if (whole && merged) {
        float* a = (float*)malloc(sizeof(float) * 4 * W * H);
        float* b = (float*)malloc(sizeof(float) * 4 * W * H);
        OK(sheafFrameGetRegion(merged, &x, &y, &fw, &fh));
        CHECK(x == 0 && y == 0 && fw == W && fh == H, "merged at (%d, %d) of %dx%d", x, y, fw, fh);
        OK(sheafFrameGetPass(whole, "combined", a, (size_t)4 * W * H));
        OK(sheafFrameGetPass(merged, "combined", b, (size_t)4 * W * H));
        CHECK(memcmp(a, b, sizeof(float) * 4 * W * H) == 0,
              "the parts saved, read back and put together differ from the whole frame");
        OK(sheafFrameGetPass(whole, "depth", a, (size_t)W * H));
        OK(sheafFrameGetPass(merged, "depth", b, (size_t)W * H));
        CHECK(memcmp(a, b, sizeof(float) * W * H) == 0, "the merged depth pass differs");
        OK(sheafFrameGetStatByName(merged, "frame.parts", &parts_stat));
        CHECK(parts_stat == 3, "frame.parts %g", parts_stat);
        free(a);
        free(b);
    }
    /* Two parts leave rows uncovered; a missing file; a half-float EXR. */
    expect_error(sheafFrameAssemble(loaded, 2, &bad), SHEAF_ERROR_RENDER,
                 "sheafFrameAssemble of two of three parts", "uncovered", "(0, 13)");
    expect_error(sheafFrameLoadImage("capi_test_no_such_part.exr", &bad), SHEAF_ERROR_IO,
                 "sheafFrameLoadImage of a missing file", "capi_test_no_such_part.exr", NULL);
    OK(sheafRendererSetString(r, "output.exr", "half"));
    OK(sheafRender(r, scene, &half));
    if (half) {
        OK(sheafFrameSaveImage(half, "capi_test_half.exr"));
        expect_error(sheafFrameLoadImage("capi_test_half.exr", &bad), SHEAF_ERROR_IO,
                     "sheafFrameLoadImage of a half-float EXR", "32-bit floats", "output.exr=float");
        sheafFrameRelease(half);
    }
    OK(sheafWriteImage("capi_test_plain.exr", 1, 1, 1, &plain, 0));
    expect_error(sheafFrameLoadImage("capi_test_plain.exr", &bad), SHEAF_ERROR_IO,
                 "sheafFrameLoadImage of an EXR not written from a frame", "sheaf:settings", NULL);
    expect_error(sheafFrameAssemble(NULL, 1, &bad), SHEAF_ERROR_INVALID_ARGUMENT,
                 "sheafFrameAssemble NULL parts", "parts", NULL);
    CHECK(bad == NULL, "a failed call returned a frame");
    for (i = 0; i < 3; ++i) {
        if (parts[i]) sheafFrameRelease(parts[i]);
        if (loaded[i]) sheafFrameRelease(loaded[i]);
    }
    if (merged) sheafFrameRelease(merged);
    if (whole) sheafFrameRelease(whole);
    OK(sheafRendererRelease(r));
    OK(sheafSceneRelease(scene));
}

/* ---- sheafWriteImage ---- */

/* Reads the first `n` bytes of a file; returns how many were read (0 when it cannot be opened). */
static size_t read_head(const char* path, unsigned char* buf, size_t n) {
    FILE* f = fopen(path, "rb");
    size_t got;
    if (!f) return 0;
    got = fread(buf, 1, n, f);
    fclose(f);
    return got;
}

static unsigned png_u32(const unsigned char* b) {
    return ((unsigned)b[0] << 24) | ((unsigned)b[1] << 16) | ((unsigned)b[2] << 8) | b[3];
}

/* A PNG of the given size, bit depth 8 and PNG colour type (0 gray, 4 gray+alpha, 2 RGB,
 * 6 RGBA), read from the IHDR chunk. */
static void check_png(const char* path, unsigned w, unsigned h, int color_type) {
    static const unsigned char kMagic[8] = {0x89, 'P', 'N', 'G', 0x0d, 0x0a, 0x1a, 0x0a};
    unsigned char head[26];
    size_t got = read_head(path, head, sizeof head);
    CHECK(got == sizeof head && memcmp(head, kMagic, 8) == 0, "%s is not a PNG", path);
    if (got != sizeof head) return;
    CHECK(memcmp(head + 12, "IHDR", 4) == 0, "%s: no IHDR first", path);
    CHECK(png_u32(head + 16) == w && png_u32(head + 20) == h, "%s: %ux%u, expected %ux%u", path,
          png_u32(head + 16), png_u32(head + 20), w, h);
    CHECK(head[24] == 8, "%s: bit depth %d, expected 8", path, head[24]);
    CHECK(head[25] == color_type, "%s: colour type %d, expected %d", path, head[25], color_type);
}

static void test_write_image(void) {
    enum { W = 5, H = 3 };
    float px[W * H * 4];
    unsigned char head[4];
    int i;
    for (i = 0; i < W * H * 4; ++i) px[i] = (float)(i % 7) / 6.0f;

    OK(sheafWriteImage("capi_test_write_gray.png", W, H, 1, px, 0));
    check_png("capi_test_write_gray.png", W, H, 0);
    OK(sheafWriteImage("capi_test_write_ga.png", W, H, 2, px, 1));
    check_png("capi_test_write_ga.png", W, H, 4);
    OK(sheafWriteImage("capi_test_write_rgb.png", W, H, 3, px, 1));
    check_png("capi_test_write_rgb.png", W, H, 2);
    OK(sheafWriteImage("capi_test_write_rgba.png", W, H, 4, px, 0));
    check_png("capi_test_write_rgba.png", W, H, 6);

    OK(sheafWriteImage("capi_test_write.exr", W, H, 4, px, 0));
    CHECK(read_head("capi_test_write.exr", head, 4) == 4 && head[0] == 0x76 && head[1] == 0x2f &&
              head[2] == 0x31 && head[3] == 0x01,
          "capi_test_write.exr is not OpenEXR");
    OK(sheafWriteImage("capi_test_write.jpg", W, H, 4, px, 1));
    CHECK(read_head("capi_test_write.jpg", head, 2) == 2 && head[0] == 0xff && head[1] == 0xd8,
          "capi_test_write.jpg is not JPEG");
    OK(sheafWriteImage("capi_test_write.hdr", W, H, 1, px, 0));
    CHECK(read_head("capi_test_write.hdr", head, 2) == 2 && head[0] == '#' && head[1] == '?',
          "capi_test_write.hdr is not Radiance HDR");

    expect_error(sheafWriteImage("capi_test_write.bogusext", W, H, 3, px, 1), SHEAF_ERROR_IO,
                 "sheafWriteImage unknown extension", "capi_test_write.bogusext", ".png");
    expect_error(sheafWriteImage("no/such/dir/capi_test_write.png", W, H, 3, px, 1),
                 SHEAF_ERROR_IO, "sheafWriteImage unwritable path", "no/such/dir", NULL);
    expect_error(sheafWriteImage("capi_test_write_bad.png", W, H, 5, px, 1),
                 SHEAF_ERROR_INVALID_ARGUMENT, "sheafWriteImage 5 channels", "channels", "5");
    expect_error(sheafWriteImage("capi_test_write_bad.png", 0, H, 3, px, 1),
                 SHEAF_ERROR_INVALID_ARGUMENT, "sheafWriteImage width 0", "0x3", NULL);
    expect_error(sheafWriteImage("capi_test_write_bad.png", W, H, 3, NULL, 1),
                 SHEAF_ERROR_INVALID_ARGUMENT, "sheafWriteImage NULL pixels", "pixels", NULL);
    expect_error(sheafWriteImage(NULL, W, H, 3, px, 1), SHEAF_ERROR_INVALID_ARGUMENT,
                 "sheafWriteImage NULL path", "path", NULL);
    CHECK(read_head("capi_test_write_bad.png", head, 1) == 0, "a failed write left a file");
}

/* ---- Scene files: a POV-Ray scene, load options, warnings ---- */

static void write_text(const char* path, const char* text) {
    FILE* f = fopen(path, "w");
    CHECK(f != NULL, "cannot write %s", path);
    if (!f) return;
    fputs(text, f);
    fclose(f);
}

static void test_scene_files(void) {
    SheafScene s = NULL;
    SheafRenderer r = NULL;
    SheafFrame frame = NULL;
    size_t count = 99;
    const char* message = NULL;
    double prims = 0;
    /* The include lives in a folder of its own, found only through the include_path option. */
    (void)system("mkdir -p capi_test_inc");
    write_text("capi_test_inc/capi_test_colors.inc", "#declare Gold = rgb <1, 0.8, 0.2>;\n");
    write_text("capi_test_scene.pov", "#include \"capi_test_colors.inc\"\n"
                                      "camera { location <0, 1, -5> look_at <0, 0, 0> }\n"
                                      "light_source { <3, 5, -4> rgb 1 }\n"
                                      "sphere { 0, 1 pigment { Gold } }\n"
                                      "box { <-2, -1, -2>, <2, -0.9, 2> pigment { rgb 1 } "
                                      "}\nglobal_settings { subsurface { } }\n");

    OK(sheafSceneNew(&s));
    expect_error(sheafSceneLoadFile(s, "capi_test_scene.pov"), SHEAF_ERROR_SCENE,
                 "include not on the path", "capi_test_colors.inc", NULL);
    OK(sheafSceneSetLoadOption(s, "include_path", "capi_test_inc"));
    OK(sheafSceneLoadFile(s, "capi_test_scene.pov"));
    OK(sheafSceneGetWarningCount(s, &count));
    CHECK(count == 1, "the scene has %zu warnings, expected 1 (subsurface)", count);
    OK(sheafSceneGetWarning(s, 0, &message));
    CHECK(message && strstr(message, "capi_test_scene.pov:6:") && strstr(message, "subsurface"),
          "warning '%s' should name the file, line 6 and subsurface", message ? message : "(null)");
    expect_error(sheafSceneGetWarning(s, 1, &message), SHEAF_ERROR_INVALID_ARGUMENT,
                 "warning out of range", "warning 1", NULL);

    OK(sheafRendererNew(&r));
    OK(sheafRendererSetInt(r, "width", 32));
    OK(sheafRendererSetInt(r, "height", 24));
    OK(sheafRender(r, s, &frame));
    OK(sheafFrameGetStatByName(frame, "scene.primitives", &prims));
    CHECK(prims == 2, "the POV scene has %g primitives, expected 2 (sphere and box)", prims);
    OK(sheafFrameRelease(frame));
    OK(sheafRendererRelease(r));

    /* Strict: the unsupported subsurface is an error, and the loaded scene stays as it was. */
    OK(sheafSceneSetLoadOption(s, "strict", "1"));
    expect_error(sheafSceneLoadFile(s, "capi_test_scene.pov"), SHEAF_ERROR_SCENE, "strict",
                 "subsurface", NULL);
    OK(sheafSceneGetWarningCount(s, &count));
    CHECK(count == 1, "a failed load changed the warnings (%zu)", count);
    expect_error(sheafSceneSetLoadOption(s, "strict", "maybe"), SHEAF_ERROR_INVALID_ARGUMENT,
                 "strict maybe", "maybe", NULL);
    expect_error(sheafSceneSetLoadOption(s, "nosuch", "1"), SHEAF_ERROR_INVALID_ARGUMENT,
                 "unknown load option", "nosuch", NULL);
    OK(sheafSceneLoadBuiltin(s, "cornell"));
    OK(sheafSceneGetWarningCount(s, &count));
    CHECK(count == 0, "a built-in scene kept %zu warnings", count);
    OK(sheafSceneRelease(s));
}

/* ---- POV-Ray animation: the clock and frame load options, and Declare ---- */

/* The primitives of the scene at `path` as loaded with the options already set. */
static double primitives_of(SheafScene s, const char* path) {
    SheafRenderer r = NULL;
    SheafFrame frame = NULL;
    double prims = -1;
    OK(sheafSceneLoadFile(s, path));
    OK(sheafRendererNew(&r));
    OK(sheafRendererSetInt(r, "width", 8));
    OK(sheafRendererSetInt(r, "height", 8));
    OK(sheafRender(r, s, &frame));
    OK(sheafFrameGetStatByName(frame, "scene.primitives", &prims));
    OK(sheafFrameRelease(frame));
    OK(sheafRendererRelease(r));
    return prims;
}

static void test_pov_animation(void) {
    SheafScene s = NULL;
    double prims = 0;
    /* One sphere per frame number; one box more while the clock is past 0.5; Extra more boxes. */
    write_text("capi_test_anim.pov",
               "camera { location <0, 1, -9> look_at 0 }\n"
               "light_source { <3, 5, -4> rgb 1 }\n"
               "#ifndef (Extra) #declare Extra = 0; #end\n"
               "#for (I, 1, frame_number) sphere { <I - 3, 0, 0>, 0.4 pigment { rgb 1 } } #end\n"
               "#if (clock > 0.5) box { -2, -1.5 pigment { rgb 1 } } #end\n"
               "#for (I, 1, Extra) box { <-3, -1, 2>, <3, -0.8, 3> pigment { rgb 1 } } #end\n"
               "#if (clock_on) #if (clock_delta != 0.25) #error \"clock_delta\" #end #end\n");
    OK(sheafSceneNew(&s));
    prims = primitives_of(s, "capi_test_anim.pov");
    CHECK(prims == 0, "a still has frame_number 0 and clock 0: %g primitives, expected 0", prims);
    /* Frames 1..5: clock 0, 0.25, 0.5, 0.75, 1 (clock_delta 0.25). */
    OK(sheafSceneSetLoadOption(s, "initial_frame", "1"));
    OK(sheafSceneSetLoadOption(s, "final_frame", "5"));
    OK(sheafSceneSetLoadOption(s, "frame", "3"));
    prims = primitives_of(s, "capi_test_anim.pov");
    CHECK(prims == 3, "frame 3 of 1..5 (clock 0.5): %g primitives, expected 3 spheres", prims);
    OK(sheafSceneSetLoadOption(s, "frame", "4"));
    prims = primitives_of(s, "capi_test_anim.pov");
    CHECK(prims == 5, "frame 4 of 1..5 (clock 0.75): %g primitives, expected 4 spheres + box",
          prims);
    /* Cyclic: 1..4 spans four steps, so clock_delta is still 0.25; frame 3 has clock 0.5. */
    OK(sheafSceneSetLoadOption(s, "final_frame", "4"));
    OK(sheafSceneSetLoadOption(s, "cyclic_animation", "1"));
    OK(sheafSceneSetLoadOption(s, "frame", "3"));
    prims = primitives_of(s, "capi_test_anim.pov");
    CHECK(prims == 3, "cyclic frame 3 of 1..4: %g primitives, expected 3", prims);
    OK(sheafSceneSetLoadOption(s, "declare", "Extra=2"));
    prims = primitives_of(s, "capi_test_anim.pov");
    CHECK(prims == 5, "Declare Extra=2: %g primitives, expected 3 + 2 boxes", prims);
    /* A frame outside the sequence, and a sequence running backwards, are refused. */
    OK(sheafSceneSetLoadOption(s, "frame", "9"));
    expect_error(sheafSceneLoadFile(s, "capi_test_anim.pov"), SHEAF_ERROR_INVALID_ARGUMENT,
                 "frame outside the sequence", "frame 9", NULL);
    OK(sheafSceneSetLoadOption(s, "frame", "1"));
    OK(sheafSceneSetLoadOption(s, "initial_frame", "6"));
    expect_error(sheafSceneLoadFile(s, "capi_test_anim.pov"), SHEAF_ERROR_INVALID_ARGUMENT,
                 "final below initial", "final_frame 4", NULL);
    expect_error(sheafSceneSetLoadOption(s, "frame", "two"), SHEAF_ERROR_INVALID_ARGUMENT,
                 "frame not a number", "two", NULL);
    expect_error(sheafSceneSetLoadOption(s, "declare", "1x=2"), SHEAF_ERROR_INVALID_ARGUMENT,
                 "declare not an identifier", "NAME=NUMBER", NULL);
    expect_error(sheafSceneSetLoadOption(s, "clock", "soon"), SHEAF_ERROR_INVALID_ARGUMENT,
                 "clock not a number", "soon", NULL);
    /* Back to a still with a clock of its own (+K): clock_on, no frames. */
    OK(sheafSceneSetLoadOption(s, "initial_frame", "1"));
    OK(sheafSceneSetLoadOption(s, "final_frame", "1"));
    OK(sheafSceneSetLoadOption(s, "declare", ""));
    OK(sheafSceneSetLoadOption(s, "clock", "0.9"));
    expect_error(sheafSceneLoadFile(s, "capi_test_anim.pov"), SHEAF_ERROR_SCENE,
                 "a still's clock_delta is 0", "clock_delta", NULL);
    OK(sheafSceneRelease(s));
}

/* ---- The reader's limits: set by load options, reported after each load ---- */

static void test_reader_limits(void) {
    SheafScene s = NULL;
    size_t count = 0;
    const char* name = NULL;
    double used = 0, limit = 0;
    write_text("capi_test_limits.pov", "camera { location <0, 1, -9> look_at 0 }\n"
                                       "light_source { <3, 5, -4> rgb 1 }\n"
                                       "#macro Ball(I) sphere { <I / 10, 0, 0>, 0.1 } #end\n"
                                       "#for (I, 1, 30) Ball(I) #end\n");
    OK(sheafSceneNew(&s));
    OK(sheafSceneGetLimitCount(s, &count));
    CHECK(count == 0, "%zu limits before any load", count);
    OK(sheafSceneLoadFile(s, "capi_test_limits.pov"));
    OK(sheafSceneGetLimitCount(s, &count));
    CHECK(count == 6, "%zu limits, expected 6", count);
    OK(sheafSceneGetLimitUse(s, 3, &name, &used, &limit));
    CHECK(strcmp(name, "loop_iterations") == 0 && used == 30 && limit == 4e6,
          "limit 3: %s %g of %g, expected loop_iterations 30 of 4e6", name, used, limit);
    OK(sheafSceneGetLimitUse(s, 1, &name, &used, &limit));
    /* The 30 spheres and the light source. */
    CHECK(strcmp(name, "objects") == 0 && used == 31, "limit 1: %s %g", name, used);
    OK(sheafSceneGetLimitUse(s, 4, &name, &used, &limit));
    CHECK(strcmp(name, "macro_calls") == 0 && used == 30 && limit == 5e6,
          "limit 4: %s %g of %g, expected macro_calls 30 of 5e6", name, used, limit);
    expect_error(sheafSceneGetLimitUse(s, 6, &name, &used, &limit), SHEAF_ERROR_INVALID_ARGUMENT,
                 "limit past the end", "does not exist", NULL);
    expect_error(sheafSceneGetLimitUse(s, 0, NULL, &used, &limit), SHEAF_ERROR_INVALID_ARGUMENT,
                 "limit without a name pointer", "name", NULL);
    /* Lowered below what the scene needs: an error at the loop; back to the default: loads. */
    OK(sheafSceneSetLoadOption(s, "limit.loop_iterations", "20"));
    expect_error(sheafSceneLoadFile(s, "capi_test_limits.pov"), SHEAF_ERROR_SCENE,
                 "a loop past limit.loop_iterations", "capi_test_limits.pov:4:2",
                 "more than 20 times");
    OK(sheafSceneSetLoadOption(s, "limit.loop_iterations", ""));
    OK(sheafSceneSetLoadOption(s, "limit.macro_calls", "29"));
    expect_error(sheafSceneLoadFile(s, "capi_test_limits.pov"), SHEAF_ERROR_SCENE,
                 "a macro call past limit.macro_calls", "capi_test_limits.pov:4:17",
                 "more than 29 macro calls");
    OK(sheafSceneSetLoadOption(s, "limit.macro_calls", ""));
    OK(sheafSceneSetLoadOption(s, "limit.objects", "30"));
    expect_error(sheafSceneLoadFile(s, "capi_test_limits.pov"), SHEAF_ERROR_SCENE,
                 "objects past limit.objects", "more than 30 objects", NULL);
    OK(sheafSceneSetLoadOption(s, "limit.objects", "31"));
    OK(sheafSceneSetLoadOption(s, "limit.data_mib", "1"));
    OK(sheafSceneSetLoadOption(s, "limit.parse_steps", "100000"));
    OK(sheafSceneLoadFile(s, "capi_test_limits.pov"));
    OK(sheafSceneGetLimitUse(s, 2, &name, &used, &limit));
    CHECK(strcmp(name, "data_mib") == 0 && limit == 1 && used > 0 && used < 1,
          "limit 2: %s %g of %g, expected data_mib under 1 of 1", name, used, limit);
    /* Bad names and values are refused, and the limits stay as they were. */
    expect_error(sheafSceneSetLoadOption(s, "limit.tokens", "5"), SHEAF_ERROR_INVALID_ARGUMENT,
                 "unknown limit", "limit.parse_steps", NULL);
    expect_error(sheafSceneSetLoadOption(s, "limit.objects", "0"), SHEAF_ERROR_INVALID_ARGUMENT,
                 "zero limit", "1..2^50", NULL);
    expect_error(sheafSceneSetLoadOption(s, "limit.objects", "-5"), SHEAF_ERROR_INVALID_ARGUMENT,
                 "negative limit", "1..2^50", NULL);
    expect_error(sheafSceneSetLoadOption(s, "limit.objects", "99999999999999999999999"),
                 SHEAF_ERROR_INVALID_ARGUMENT, "limit out of range", "1..2^50", NULL);
    expect_error(sheafSceneSetLoadOption(s, "limit.objects", "12x"), SHEAF_ERROR_INVALID_ARGUMENT,
                 "limit not a number", "1..2^50", NULL);
    OK(sheafSceneLoadFile(s, "capi_test_limits.pov"));
    /* A built-in scene has no reader limits. */
    OK(sheafSceneLoadBuiltin(s, "cornell"));
    OK(sheafSceneGetLimitCount(s, &count));
    CHECK(count == 0, "%zu limits after a built-in scene", count);
    OK(sheafSceneRelease(s));
    remove("capi_test_limits.pov");
}

/* ---- Object flags and the preset list ---- */

static void test_flags_and_presets(void) {
    SheafScene s = build_scene();
    SheafRenderer r = NULL;
    SheafFrame plain = NULL, ghost = NULL;
    double a = 0, b = 0;
    size_t needed = 0;
    char* list;

    OK(sheafRendererNew(&r));
    OK(sheafRendererSetInt(r, "width", 32));
    OK(sheafRendererSetInt(r, "height", 24));
    OK(sheafRender(r, s, &plain));
    /* Object 1 no longer seen by the camera: fewer primary hits on it, the same ray tests. */
    OK(sheafSceneSetObjectFlags(s, 1, SHEAF_OBJECT_NO_IMAGE));
    OK(sheafRender(r, s, &ghost));
    OK(sheafFrameGetStatByName(plain, "rays.primary", &a));
    OK(sheafFrameGetStatByName(ghost, "rays.primary", &b));
    CHECK(a == b, "primary rays %g vs %g", a, b);
    {
        float ids_plain[32 * 24], ids_ghost[32 * 24];
        int i, seen_plain = 0, seen_ghost = 0;
        OK(sheafFrameGetPass(plain, "object_id", ids_plain, 32 * 24));
        OK(sheafFrameGetPass(ghost, "object_id", ids_ghost, 32 * 24));
        for (i = 0; i < 32 * 24; ++i) {
            seen_plain += ids_plain[i] == 1.0f;
            seen_ghost += ids_ghost[i] == 1.0f;
        }
        CHECK(seen_plain > 0 && seen_ghost == 0, "object 1 seen on %d then %d pixels",
              seen_plain, seen_ghost);
    }
    expect_error(sheafSceneSetObjectFlags(s, 99, 0), SHEAF_ERROR_INVALID_ARGUMENT,
                 "flags of a missing object", "object 99", NULL);
    expect_error(sheafSceneSetObjectFlags(s, 0, 64), SHEAF_ERROR_INVALID_ARGUMENT,
                 "unknown flag bits", "64", NULL);
    expect_error(sheafSceneSetLoadOption(s, "subdivision.boundary", "round"),
                 SHEAF_ERROR_INVALID_ARGUMENT, "bad boundary rule", "round", NULL);
    OK(sheafSceneSetLoadOption(s, "subdivision.limit", "1"));

    OK(sheafGetPresetList(NULL, 0, &needed));
    CHECK(needed > 1, "the preset list is empty");
    list = (char*)malloc(needed);
    OK(sheafGetPresetList(list, needed, &needed));
    CHECK(strstr(list, "crsh\t") != NULL && strstr(list, "rah\t") != NULL &&
              strstr(list, "brute\t") != NULL,
          "the preset list lacks the papers' presets: %s", list);
    free(list);

    OK(sheafFrameRelease(plain));
    OK(sheafFrameRelease(ghost));
    OK(sheafRendererRelease(r));
    OK(sheafSceneRelease(s));
}

int main(void) {
    sheafSetErrorCallback(on_error, &g_callback_calls);
    test_version();
    test_settings();
    test_null_arguments();
    test_scene_errors();
    test_render_scene();
    test_crsh_matches_brute();
    test_write_image();
    test_regions();
    test_scene_files();
    test_pov_animation();
    test_reader_limits();
    test_flags_and_presets();
    CHECK(g_callback_calls == g_expected_errors, "error callback called %d times for %d errors",
          g_callback_calls, g_expected_errors);
    sheafSetErrorCallback(NULL, NULL);

    if (g_failures) {
        fprintf(stderr, "capi_test: %d of %d checks failed\n", g_failures, g_checks);
        return 1;
    }
    printf("capi_test: all %d checks passed\n", g_checks);
    return 0;
}
