/* A C host of tissue (tissue/tissue_c.h, target tissue::tissue_c): the data liver with its
 * scenario, poked from above by the host's instrument; prints the tool force and writes a PNG,
 * then checks what a host relies on: a non-zero force, a non-blank image, and a missing mesh
 * refused with the file named. Exit 0 when all hold.
 *
 *   c_host DATA_DIR OUT.png      (DATA_DIR: the project's data/ folder) */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#include <stb/stb_image.h>

#include <tissue/tissue_c.h>

static int failed(const char* what) {
  fprintf(stderr, "c_host: %s: %s\n", what, tissue_last_error());
  return 1;
}

/* Pixels that differ from the scene's background (sRGB 13, 13, 15) by more than a few levels. */
static long covered_pixels(const char* png) {
  int w = 0, h = 0, n = 0;
  unsigned char* p = stbi_load(png, &w, &h, &n, 4);
  long covered = 0;
  if (!p) return -1;
  for (long i = 0; i < (long)w * h; ++i)
    if (abs(p[4 * i] - 13) + abs(p[4 * i + 1] - 13) + abs(p[4 * i + 2] - 15) > 12) ++covered;
  stbi_image_free(p);
  return covered;
}

int main(int argc, char** argv) {
  char material[4096], scenario[4096], chosen[64];
  long pending = 0;
  tissue_scene* scene = NULL;
  tissue_organ* liver = NULL;
  tissue_organ* none = NULL;
  float force[3] = {0, 0, 0};
  float deepest = 0.0f;
  long covered;
  int frame, status = 0;
  if (argc != 3) {
    fprintf(stderr, "usage: c_host DATA_DIR OUT.png\n");
    return 2;
  }
  snprintf(material, sizeof material, "%s/materials/liver.json", argv[1]);
  snprintf(scenario, sizeof scenario, "%s/scenarios/liver_poke_grasp.json", argv[1]);

  /* 1 a scene on tissue's own headless context, and the liver as its scenario describes it */
  if (tissue_scene_create(NULL, &scene) != 0) return failed("tissue_scene_create");
  if (tissue_organ_add(scene, NULL, material, scenario, &liver) != 0) {
    status = failed("tissue_organ_add");
    goto done;
  }
  /* 2 one second to settle, then the host's instrument (8 mm sphere) comes down 10 mm into
   * the top of the liver over 100 frames of 1/60 s */
  for (frame = 0; frame < 60; ++frame)
    if (tissue_scene_step(scene, 1.0 / 60.0) != 0) {
      status = failed("tissue_scene_step");
      goto done;
    }
  for (frame = 0; frame <= 100; ++frame) {
    const float z = 75.0f - 25.7f * (float)frame / 100.0f;
    if (tissue_instrument_set_pose(scene, 31.82f, 0.0f, z, 8.0f) != 0 ||
        tissue_scene_step(scene, 1.0 / 60.0) != 0) {
      status = failed("poke");
      goto done;
    }
  }
  if (tissue_instrument_force(scene, force) != 0) {
    status = failed("tissue_instrument_force");
    goto done;
  }
  deepest = sqrtf(force[0] * force[0] + force[1] * force[1] + force[2] * force[2]);
  printf("c_host: force on the instrument at 10 mm: (%.3f, %.3f, %.3f) N, |F| = %.3f N\n", force[0], force[1],
         force[2], deepest);
  /* 3 the poked liver, separable SSS, into a PNG */
  if (tissue_organ_set_method(liver, "separable") != 0 ||
      tissue_scene_render_png(scene, argv[2], 480, 360) != 0) {
    status = failed("render");
    goto done;
  }
  covered = covered_pixels(argv[2]);
  printf("c_host: %s: %ld of %d pixels show the organ or the instrument\n", argv[2], covered, 480 * 360);
  /* 4 what a host relies on */
  if (!(deepest > 0.05f)) {
    fprintf(stderr, "c_host: the force at 10 mm is %.4f N; expected more than 0.05 N\n", deepest);
    status = 1;
  }
  if (covered < 480L * 360L / 20) {
    fprintf(stderr, "c_host: %s is (nearly) blank\n", argv[2]);
    status = 1;
  }
  if (tissue_organ_add(scene, "no/such/organ.obj", NULL, NULL, &none) == 0 || none != NULL ||
      strstr(tissue_last_error(), "no/such/organ.obj") == NULL) {
    fprintf(stderr, "c_host: a missing mesh must fail naming it; got '%s'\n", tissue_last_error());
    status = 1;
  } else {
    printf("c_host: a missing mesh is refused: %s\n", tissue_last_error());
  }
  if (tissue_organ_set_method(liver, "phong") == 0) {
    fprintf(stderr, "c_host: an unknown method must fail\n");
    status = 1;
  }
  /* 5 a frame budget (issue 16): refused when negative; under one the controller picks the
   * liver's method and says which */
  if (tissue_scene_set_budget_ms(scene, -1.0) == 0 || strstr(tissue_last_error(), "budget") == NULL) {
    fprintf(stderr, "c_host: a negative budget must fail naming it; got '%s'\n", tissue_last_error());
    status = 1;
  }
  if (tissue_scene_set_budget_ms(scene, 1000.0) != 0 ||
      tissue_scene_prepare_budget_options(scene, &pending) != 0 ||
      tissue_scene_render_png(scene, argv[2], 480, 360) != 0 ||
      tissue_organ_chosen_method(liver, chosen, (int)sizeof chosen) != 0 || chosen[0] == '\0') {
    status = failed("budget");
    goto done;
  }
  printf(
      "c_host: under a 1000 ms budget (%ld method settings built first) the controller draws the liver %s\n",
      pending, chosen);
done:
  tissue_scene_destroy(scene);
  return status;
}
