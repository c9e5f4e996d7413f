/* The C ABI's description structs from plain C99: lights (point, spot, parallel, shadowless,
 * fade), cameras (orthographic, shifted, fisheye) and emissive materials, checked against the
 * radiance they must give; bad enum values are INVALID_ARGUMENT. Exits non-zero on any failure. */
#include <sheaf/sheaf.h>

#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"

/* A 4x4 quad in the plane z = 0 facing +z, seen by an orthographic camera from +z. */
static SheafScene quad_scene(const SheafMaterialDesc* mat) {
    static const float pos[] = {-2, -2, 0, 2, -2, 0, 2, 2, 0, -2, 2, 0};
    static const uint32_t idx[] = {0, 1, 2, 0, 2, 3};
    SheafScene s = NULL;
    uint32_t mesh = 0, m = 0;
    SheafCameraDesc cam;
    OK(sheafSceneNew(&s));
    OK(sheafSceneAddMaterial(s, mat, &m));
    OK(sheafSceneAddMesh(s, pos, 4, idx, 2, NULL, &mesh));
    OK(sheafSceneAddObject(s, mesh, m, NULL, "quad", NULL));
    sheafCameraDescInit(&cam);
    cam.projection = SHEAF_PROJECTION_ORTHOGRAPHIC;
    cam.position[0] = 0, cam.position[1] = 0, cam.position[2] = 5;
    cam.look_at[0] = 0, cam.look_at[1] = 0, cam.look_at[2] = 0;
    cam.ortho_height = 1.0f;
    OK(sheafSceneSetCameraDesc(s, &cam));
    return s;
}

/* Red channel of the centre pixel of a 9x9 render. */
static float centre_red(SheafScene s) {
    SheafRenderer r = NULL;
    SheafFrame f = NULL;
    float px[9 * 9 * 4] = {0};
    OK(sheafRendererNew(&r));
    OK(sheafRendererSetInt(r, "width", 9));
    OK(sheafRendererSetInt(r, "height", 9));
    OK(sheafRender(r, s, &f));
    OK(sheafFrameGetPass(f, "combined", px, sizeof px / sizeof px[0]));
    sheafFrameRelease(f);
    sheafRendererRelease(r);
    return px[(4 * 9 + 4) * 4];
}

int main(void) {
    SheafMaterialDesc mat;
    SheafLightDesc light;
    SheafScene s;
    SheafCameraDesc cam;
    uint32_t id = 99;
    float red;

    sheafMaterialDescInit(&mat);
    mat.color[0] = mat.color[1] = mat.color[2] = 1.0f;
    mat.ambient = 0.1f, mat.diffuse = 0.6f, mat.specular = 0.0f;
    CHECK(mat.emission[0] == 0 && mat.emission[1] == 0 && mat.emission[2] == 0, "default emission");

    /* A parallel light at 60 degrees from the normal: ambient + diffuse * cos 60. */
    s = quad_scene(&mat);
    sheafLightDescInit(&light);
    CHECK(light.type == SHEAF_LIGHT_POINT && light.color[0] == 1.0f, "light defaults");
    light.type = SHEAF_LIGHT_PARALLEL;
    light.direction[0] = 0, light.direction[1] = -sqrtf(3.0f), light.direction[2] = -1;
    OK(sheafSceneAddLight(s, &light, &id));
    CHECK(id == 0, "first light id %u", id);
    red = centre_red(s);
    CHECK(fabsf(red - (0.1f + 0.6f * 0.5f)) < 1e-4f, "parallel light: %f", red);
    sheafSceneRelease(s);

    /* A spot pointing away: ambient only. */
    s = quad_scene(&mat);
    sheafLightDescInit(&light);
    light.type = SHEAF_LIGHT_SPOT;
    light.position[2] = 3;
    light.direction[0] = 1, light.direction[1] = 0, light.direction[2] = 0;
    light.spot_radius = 10, light.spot_falloff = 20;
    OK(sheafSceneAddLight(s, &light, NULL));
    red = centre_red(s);
    CHECK(fabsf(red - 0.1f) < 1e-4f, "spot pointing away: %f", red);
    sheafSceneRelease(s);

    /* An emissive, otherwise black surface shows its emission exactly. */
    mat.ambient = 0, mat.diffuse = 0;
    mat.emission[0] = 0.5f;
    s = quad_scene(&mat);
    red = centre_red(s);
    CHECK(fabsf(red - 0.5f) < 1e-6f, "emission: %f", red);

    /* Bad enums and NULLs are argument errors, not crashes: every value outside each enum
     * (the C ABI takes enums as int, so no value is undefined behaviour to pass). */
    {
        const int bad_light[] = {-1, 3, 7, 256, 65536, INT_MAX, INT_MIN};
        const int bad_projection[] = {-1, 11, 255, 65536, INT_MAX, INT_MIN};
        size_t i;
        for (i = 0; i < sizeof bad_light / sizeof bad_light[0]; ++i) {
            sheafLightDescInit(&light);
            light.type = bad_light[i];
            CHECK(sheafSceneAddLight(s, &light, NULL) == SHEAF_ERROR_INVALID_ARGUMENT,
                  "light type %d", bad_light[i]);
        }
        for (i = 0; i < sizeof bad_projection / sizeof bad_projection[0]; ++i) {
            sheafCameraDescInit(&cam);
            cam.projection = bad_projection[i];
            CHECK(sheafSceneSetCameraDesc(s, &cam) == SHEAF_ERROR_INVALID_ARGUMENT,
                  "projection %d", bad_projection[i]);
        }
    }
    CHECK(sheafSceneAddLight(s, NULL, NULL) == SHEAF_ERROR_INVALID_ARGUMENT, "NULL light");
    sheafCameraDescInit(&cam);
    CHECK(sheafSceneSetCameraLens(s, 0, 180, NULL) == SHEAF_ERROR_INVALID_ARGUMENT, "angle 0");
    {
        const float flat[3] = {1, 0, 1};
        CHECK(sheafSceneSetCameraLens(s, 90, 180, flat) == SHEAF_ERROR_INVALID_ARGUMENT,
              "a zero length");
    }
    CHECK(sheafSceneSetCameraFocus(s, -1, 4) == SHEAF_ERROR_INVALID_ARGUMENT, "lens radius < 0");
    CHECK(sheafSceneSetCameraFocus(s, 0.5f, 0) == SHEAF_ERROR_INVALID_ARGUMENT,
          "a lens without a focal distance");
    CHECK(sheafSceneSetCameraFocus(NULL, 0, 0) == SHEAF_ERROR_INVALID_ARGUMENT, "NULL scene");
    /* A spot with a falloff of 0 is rejected when the scene is committed. */
    sheafLightDescInit(&light);
    light.type = SHEAF_LIGHT_SPOT;
    light.spot_falloff = 0;
    OK(sheafSceneAddLight(s, &light, NULL));
    CHECK(sheafSceneCommit(s) == SHEAF_ERROR_SCENE, "spot with falloff 0");
    sheafSceneRelease(s);

    /* A fisheye camera (a traced projection): 180 degrees across its circle, the quad in the
     * middle, the grey background around it, and no ray (black) outside the circle. */
    {
        SheafRenderer r = NULL;
        SheafFrame f = NULL;
        float px[9 * 9 * 4] = {0};
        const float grey[3] = {0.5f, 0.5f, 0.5f};
        double camera_rays = 0;
        sheafMaterialDescInit(&mat);
        mat.emission[0] = 1.0f;
        s = quad_scene(&mat);
        OK(sheafSceneSetBackground(s, grey));
        sheafCameraDescInit(&cam);
        cam.projection = SHEAF_PROJECTION_FISHEYE;
        cam.position[2] = 5;
        cam.look_at[0] = cam.look_at[1] = cam.look_at[2] = 0;
        OK(sheafSceneSetCameraDesc(s, &cam));
        OK(sheafSceneSetCameraLens(s, 180, 180, NULL));
        OK(sheafRendererNew(&r));
        OK(sheafRendererSetInt(r, "width", 9));
        OK(sheafRendererSetInt(r, "height", 9));
        OK(sheafRender(r, s, &f));
        OK(sheafFrameGetPass(f, "combined", px, sizeof px / sizeof px[0]));
        OK(sheafFrameGetStatByName(f, "rays.camera", &camera_rays));
        CHECK(px[(4 * 9 + 4) * 4] > 0.9f, "the quad at the fisheye's centre");
        CHECK(fabsf(px[(0 * 9 + 4) * 4] - 0.5f) < 1e-3f, "the background inside the circle");
        CHECK(px[0] == 0.0f && px[1] == 0.0f && px[2] == 0.0f, "black outside the circle");
        CHECK(camera_rays > 40 && camera_rays < 81, "camera rays inside the circle only");
        /* A lens on a fisheye is refused at commit; sheafSceneSetCameraDesc resets it. */
        OK(sheafSceneSetCameraFocus(s, 0.2f, 5));
        CHECK(sheafSceneCommit(s) == SHEAF_ERROR_SCENE, "a lens on a fisheye");
        sheafFrameRelease(f);
        f = NULL;
        cam.projection = SHEAF_PROJECTION_PERSPECTIVE;
        OK(sheafSceneSetCameraDesc(s, &cam));
        OK(sheafSceneCommit(s));
        /* Depth of field: a lens sharp on the quad's plane (5 ahead) traces the camera rays,
         * 2 x 2 samples a pixel; the quad's middle stays as bright. */
        OK(sheafSceneSetCameraFocus(s, 0.3f, 5));
        OK(sheafRendererSetInt(r, "aa.samples", 2));
        OK(sheafRender(r, s, &f));
        OK(sheafFrameGetPass(f, "combined", px, sizeof px / sizeof px[0]));
        OK(sheafFrameGetStatByName(f, "rays.camera", &camera_rays));
        CHECK(camera_rays == 9 * 9 * 4, "every sample's camera ray traced: %g", camera_rays);
        CHECK(px[(4 * 9 + 4) * 4] > 0.9f, "the quad sharp at the centre: %f", px[(4 * 9 + 4) * 4]);
        sheafFrameRelease(f);
        sheafRendererRelease(r);
        sheafSceneRelease(s);
    }

    /* Passes as false-colour pictures; an unknown pass is an argument error. */
    {
        SheafRenderer r = NULL;
        SheafFrame f = NULL;
        sheafMaterialDescInit(&mat);
        s = quad_scene(&mat);
        OK(sheafRendererNew(&r));
        OK(sheafRendererSetInt(r, "width", 8));
        OK(sheafRendererSetInt(r, "height", 8));
        OK(sheafRender(r, s, &f));
        OK(sheafFrameSavePass(f, "tests", "capi_desc_tests_pass.png"));
        OK(sheafFrameSavePass(f, "normal", "capi_desc_normal_pass.png"));
        CHECK(sheafFrameSavePass(f, "velocity", "x.png") == SHEAF_ERROR_INVALID_ARGUMENT,
              "unknown pass");
        CHECK(sheafFrameSavePass(f, "depth", "x.exr") == SHEAF_ERROR_IO,
              "false colour needs 8 bits");
        OK(sheafRendererSetString(r, "output.display", "Rec.709"));
        sheafFrameRelease(f);
        OK(sheafRender(r, s, &f));
        OK(sheafFrameSaveImage(f, "capi_desc_rec709.png"));
        OK(sheafRendererSetString(r, "output.display", "P3"));
        sheafFrameRelease(f);
        OK(sheafRender(r, s, &f));
        CHECK(sheafFrameSaveImage(f, "capi_desc_p3.png") == SHEAF_ERROR_IO, "unknown display");
        sheafFrameRelease(f);
        sheafRendererRelease(r);
        sheafSceneRelease(s);
    }

    /* Textures: a missing file fails the commit naming it; bad mappings and uv counts are
     * argument errors. (Textures that render are tested in io/image/texture_sampler_test.) */
    {
        uint32_t tex = 99;
        const float uvs[8] = {0, 0, 1, 0, 1, 1, 0, 1};
        const char* msg = NULL;
        sheafMaterialDescInit(&mat);
        CHECK(mat.texture == -1, "default texture %d", (int)mat.texture);
        s = quad_scene(&mat);
        OK(sheafSceneAddTexture(s, "/nonexistent/checker.png", SHEAF_MAPPING_UV, NULL, NULL, &tex));
        CHECK(tex == 0, "first texture id %u", tex);
        OK(sheafSceneSetMeshUvs(s, 0, uvs, 4));
        CHECK(sheafSceneSetMeshUvs(s, 0, uvs, 3) == SHEAF_ERROR_INVALID_ARGUMENT, "uv count");
        {
            const int bad[] = {-1, 5, 9, 256, INT_MAX, INT_MIN};
            size_t i;
            for (i = 0; i < sizeof bad / sizeof bad[0]; ++i)
                CHECK(sheafSceneAddTexture(s, "x.png", bad[i], NULL, NULL, NULL) ==
                          SHEAF_ERROR_INVALID_ARGUMENT,
                      "mapping %d", bad[i]);
        }
        mat.texture = 0;
        OK(sheafSceneAddMaterial(s, &mat, NULL));
        CHECK(sheafSceneCommit(s) == SHEAF_ERROR_SCENE, "missing texture");
        sheafGetLastError(&msg);
        CHECK(msg && strstr(msg, "/nonexistent/checker.png"), "message: %s", msg ? msg : "(null)");
        sheafSceneRelease(s);
    }

    if (g_failures)
        fprintf(stderr, "%d failures\n", g_failures);
    else
        printf("capi_desc: all checks passed\n");
    return g_failures ? 1 : 0;
}
