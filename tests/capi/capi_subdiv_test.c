/* sheafSceneAddSubdivisionMesh from plain C99: a cube cage refined by Catmull-Clark (the
 * triangle count per level through the frame's scene.primitives), Loop on an octahedron, creases
 * and texture coordinates, the mesh rendering where it should, and bad cages as errors that
 * leave the scene as it was. Exits non-zero on any failure. */
#include <sheaf/sheaf.h>

#include <limits.h>
#include <stdio.h>
#include <string.h>

#include "check.h"

static const float cube_positions[] = {-1, -1, -1, 1, -1, -1, -1, 1, -1, 1, 1, -1,
                                       -1, -1, 1,  1, -1, 1,  -1, 1, 1,  1, 1, 1};
static const uint32_t cube_sizes[] = {4, 4, 4, 4, 4, 4};
static const uint32_t cube_faces[] = {0, 2, 3, 1, 4, 5, 7, 6, 0, 1, 5, 4,
                                      2, 6, 7, 3, 0, 4, 6, 2, 1, 3, 7, 5};

static const float octa_positions[] = {1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1};
static const uint32_t octa_sizes[] = {3, 3, 3, 3, 3, 3, 3, 3};
static const uint32_t octa_faces[] = {0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4,
                                      2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5};

/* Renders the scene at 16 x 16 and returns its primitive count; *centre_hit is whether the
 * centre pixel sees an object, *corner_hit whether the top-left one does. */
static double render(SheafScene s, int* centre_hit, int* corner_hit) {
    SheafRenderer r = NULL;
    SheafFrame f = NULL;
    float ids[16 * 16];
    double primitives = -1;
    OK(sheafRendererNew(&r));
    OK(sheafRendererSetInt(r, "width", 16));
    OK(sheafRendererSetInt(r, "height", 16));
    OK(sheafRender(r, s, &f));
    OK(sheafFrameGetStatByName(f, "scene.primitives", &primitives));
    OK(sheafFrameGetPass(f, "object_id", ids, 16 * 16));
    *centre_hit = ids[8 * 16 + 8] >= 0;
    *corner_hit = ids[0] >= 0;
    sheafFrameRelease(f);
    sheafRendererRelease(r);
    return primitives;
}

/* A scene with the default material, a light and a camera looking at the origin from +z. */
static SheafScene new_scene(void) {
    static const float light[3] = {2, 4, 6}, white[3] = {1, 1, 1};
    static const float eye[3] = {0, 0, 8}, at[3] = {0, 0, 0}, up[3] = {0, 1, 0};
    SheafScene s = NULL;
    SheafMaterialDesc m;
    sheafMaterialDescInit(&m);
    OK(sheafSceneNew(&s));
    OK(sheafSceneAddMaterial(s, &m, NULL));
    OK(sheafSceneAddPointLight(s, light, white));
    OK(sheafSceneSetCamera(s, eye, at, up, 40.0f));
    return s;
}

static SheafError add_cube(SheafScene s, int level, uint32_t* id) {
    return sheafSceneAddSubdivisionMesh(s, cube_positions, 8, cube_sizes, 6, cube_faces, NULL, NULL,
                                        0, NULL, SHEAF_SUBDIV_CATMULL_CLARK, level, id);
}

static void expect_error(SheafError got, SheafError want, const char* text) {
    const char* message = "";
    sheafGetLastError(&message);
    CHECK(got == want, "returned %d, expected %d (%s)", (int)got, (int)want, message);
    CHECK(strstr(message, text) != NULL, "message '%s' lacks '%s'", message, text);
}

int main(void) {
    static const unsigned quads[] = {6, 24, 96, 384};
    int level, centre = 0, corner = 0;
    uint32_t id = 99;

    /* Catmull-Clark: 6 * 4^(level-1) quads from level 1, two triangles each. */
    for (level = 0; level <= 3; ++level) {
        SheafScene s = new_scene();
        OK(add_cube(s, level, &id));
        CHECK(id == 0, "first mesh id %u", id);
        OK(sheafSceneAddObject(s, id, 0, NULL, "cube", NULL));
        CHECK(render(s, &centre, &corner) == 2.0 * quads[level], "level %d triangle count", level);
        CHECK(centre && !corner, "level %d: the cube is not where it should be", level);
        sheafSceneRelease(s);
    }

    /* Loop on the octahedron, with creases and texture coordinates. */
    {
        static const uint32_t creases[] = {0, 2, 2, 4};
        static const float sharpness[] = {2.0f, 10.0f};
        float uvs[12];
        int i;
        SheafScene s = new_scene();
        for (i = 0; i < 6; ++i) uvs[2 * i] = octa_positions[3 * i], uvs[2 * i + 1] = 0.5f;
        OK(sheafSceneAddSubdivisionMesh(s, octa_positions, 6, octa_sizes, 8, octa_faces, creases,
                                        sharpness, 2, uvs, SHEAF_SUBDIV_LOOP, 2, &id));
        OK(sheafSceneAddObject(s, id, 0, NULL, "octahedron", NULL));
        CHECK(render(s, &centre, &corner) == 8.0 * 16, "Loop level 2 triangle count");
        CHECK(centre && !corner, "the octahedron is not where it should be");
        sheafSceneRelease(s);
    }

    /* Errors: nothing is added, the next mesh still gets id 0, messages name the problem. */
    {
        static const uint32_t bad_faces[] = {0, 2, 3, 9, 4, 5, 7, 6, 0, 1, 5, 4,
                                             2, 6, 7, 3, 0, 4, 6, 2, 1, 3, 7, 5};
        static const uint32_t two[] = {2, 4, 4, 4, 4, 4};
        static const uint32_t not_an_edge[] = {0, 7};
        static const float sharp[] = {1.0f};
        SheafScene s = new_scene();
        expect_error(sheafSceneAddSubdivisionMesh(NULL, cube_positions, 8, cube_sizes, 6,
                                                  cube_faces, NULL, NULL, 0, NULL,
                                                  SHEAF_SUBDIV_CATMULL_CLARK, 1, &id),
                     SHEAF_ERROR_INVALID_ARGUMENT, "'scene' is NULL");
        {
            const int bad[] = {-1, 2, 7, 256, INT_MAX, INT_MIN};
            size_t i;
            for (i = 0; i < sizeof bad / sizeof bad[0]; ++i)
                expect_error(sheafSceneAddSubdivisionMesh(s, cube_positions, 8, cube_sizes, 6,
                                                          cube_faces, NULL, NULL, 0, NULL, bad[i],
                                                          1, &id),
                             SHEAF_ERROR_INVALID_ARGUMENT, "is not one of SHEAF_SUBDIV");
        }
        expect_error(add_cube(s, 9, &id), SHEAF_ERROR_INVALID_ARGUMENT, "level 9 is out of range");
        expect_error(add_cube(s, -1, &id), SHEAF_ERROR_INVALID_ARGUMENT, "out of range");
        expect_error(sheafSceneAddSubdivisionMesh(s, cube_positions, 8, cube_sizes, 6, bad_faces,
                                                  NULL, NULL, 0, NULL, SHEAF_SUBDIV_CATMULL_CLARK,
                                                  1, &id),
                     SHEAF_ERROR_SCENE, "names vertex 9, out of range");
        expect_error(sheafSceneAddSubdivisionMesh(s, cube_positions, 8, two, 6, cube_faces, NULL,
                                                  NULL, 0, NULL, SHEAF_SUBDIV_CATMULL_CLARK, 1,
                                                  &id),
                     SHEAF_ERROR_SCENE, "face 0 has 2 vertices");
        expect_error(sheafSceneAddSubdivisionMesh(s, cube_positions, 8, cube_sizes, 6, cube_faces,
                                                  NULL, NULL, 0, NULL, SHEAF_SUBDIV_LOOP, 1, &id),
                     SHEAF_ERROR_SCENE, "Loop subdivision needs a cage of triangles");
        expect_error(sheafSceneAddSubdivisionMesh(s, cube_positions, 8, cube_sizes, 6, cube_faces,
                                                  not_an_edge, sharp, 1, NULL,
                                                  SHEAF_SUBDIV_CATMULL_CLARK, 1, &id),
                     SHEAF_ERROR_SCENE, "not an edge of the cage");
        expect_error(sheafSceneAddSubdivisionMesh(s, cube_positions, 8, cube_sizes, 6, cube_faces,
                                                  NULL, NULL, 1, NULL, SHEAF_SUBDIV_CATMULL_CLARK,
                                                  1, &id),
                     SHEAF_ERROR_INVALID_ARGUMENT, "'crease_edges' is NULL");
        OK(add_cube(s, 1, &id));
        CHECK(id == 0, "after failed calls the first mesh id is %u", id);
        sheafSceneRelease(s);
    }

    if (g_failures) {
        fprintf(stderr, "%d of %d checks failed\n", g_failures, g_checks);
        return 1;
    }
    printf("%d checks passed\n", g_checks);
    return 0;
}
