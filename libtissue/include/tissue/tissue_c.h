/* tissue's C API for engine plugins (Unity P/Invoke, Unreal, any C host): opaque handles, int
 * return codes (0 = success), the message of the last failure on this thread from
 * tissue_last_error(), and no exception ever crosses the boundary. Shared library tissue_c
 * (CMake: tissue::tissue_c).
 *
 * Units: mm, s, N; model matrices column-major, object mm to world mm.
 * GL: tissue_scene_create, tissue_organ_add, tissue_scene_render, tissue_scene_render_png and
 * tissue_scene_destroy need the GL context current: the host's (create given its
 * get_proc_address) or the scene's own headless one, which they make current themselves. The
 * other calls never touch GL; tissue_scene_step (simulation and mesh update) may run on another
 * thread than the render, but not at the same time as a call on the same scene.
 * The state contract: tissue_scene_render restores every piece of GL state it changes (the list
 * is render::Renderer::renderTo's, docs/EMBEDDING.md). */
#ifndef TISSUE_TISSUE_C_H
#define TISSUE_TISSUE_C_H

#if defined(_WIN32)
#define TISSUE_C_API __declspec(dllexport)
#else
#define TISSUE_C_API __attribute__((visibility("default")))
#endif

#ifdef __cplusplus
extern "C" {
#endif

typedef struct tissue_scene tissue_scene; /* a scene of organs, its renderer and instrument */
typedef struct tissue_organ tissue_organ; /* an organ of a scene; freed with its scene */

/* Return codes. */
#define TISSUE_OK 0
#define TISSUE_ERROR_ARGUMENT 1 /* a NULL handle or pointer, a bad number or name */
#define TISSUE_ERROR_FILE 2     /* a file is missing or malformed (the message names it) */
#define TISSUE_ERROR_GL 3       /* no context, or a GL failure */
#define TISSUE_ERROR_INTERNAL 4 /* anything else (the message says what) */

/* The message of the last failure on this thread ("" when none); valid until the next failing
 * call on this thread. */
TISSUE_C_API const char* tissue_last_error(void);

/* Creates a scene. With get_proc_address (the host's context current), tissue renders with the
 * host's context; with NULL, it creates its own headless context (EGL, then OSMesa). */
TISSUE_C_API int tissue_scene_create(void* (*get_proc_address)(const char*), tissue_scene** out);
/* Frees the scene and its organs (NULL is a no-op; the host's context current if it gave one). */
TISSUE_C_API void tissue_scene_destroy(tissue_scene* scene);

/* Adds an organ: mesh (OBJ/PLY/OFF/STL, mm; NULL with a scenario: the scenario's mesh), its
 * material file (data/materials/<organ>.json; NULL: a default organ material) and a scenario
 * (data/scenarios/<name>.json: simulated as it describes; NULL: a static organ). */
TISSUE_C_API int tissue_organ_add(tissue_scene* scene, const char* mesh_path, const char* material_path,
                                  const char* scenario_path_or_null, tissue_organ** out);
/* "lit", "separable", "texture-space", "ray-march" or "parallax". */
TISSUE_C_API int tissue_organ_set_method(tissue_organ* organ, const char* method);
/* Column-major 4x4, object mm to world mm: rigid motion and uniform scale. */
TISSUE_C_API int tissue_organ_set_transform(tissue_organ* organ, const float model[16]);

/* The instrument tip's centre in world mm and its radius (mm; <= 0 keeps the scenario's), for
 * the next step; the scenario's scripted path stops. */
TISSUE_C_API int tissue_instrument_set_pose(tissue_scene* scene, float x_mm, float y_mm, float z_mm,
                                            float radius_mm);
/* Grasps (non-zero) or releases (0) at the next step. */
TISSUE_C_API int tissue_instrument_grasp(tissue_scene* scene, int grasp);
/* The last step's force on the tool, N, world space. */
TISSUE_C_API int tissue_instrument_force(const tissue_scene* scene, float force_N[3]);
/* Draws the scenario's instrument (non-zero, the default) or leaves it to the host (0). */
TISSUE_C_API int tissue_instrument_set_visible(tissue_scene* scene, int visible);

/* A fixed camera (mm, degrees): use the host's own when depth is shared. Without it, the camera
 * frames all organs. */
TISSUE_C_API int tissue_scene_set_camera(tissue_scene* scene, const float eye[3], const float target[3],
                                         const float up[3], float fov_y_deg);
/* Near and far clipping distances (mm), as the host's projection has them (defaults 1, 2000). */
TISSUE_C_API int tissue_scene_set_clip(tissue_scene* scene, float near_mm, float far_mm);

/* Simulates dt_s seconds (fixed scenario frames as time accumulates; at most 4 per call) and
 * updates the meshes. No GL. */
TISSUE_C_API int tissue_scene_step(tissue_scene* scene, double dt_s);

/* Renders into the host's framebuffer (GL name; 0 = the default one), viewport (0, 0, width,
 * height). By default tissue is depth-tested against what the host drew and writes its depth,
 * and only pixels it covers are written (tissue_scene_set_host_depth changes that). */
TISSUE_C_API int tissue_scene_render(tissue_scene* scene, unsigned int framebuffer, int width, int height);
/* share_depth: test against and write the host's depth (1, default) or ignore it (0);
 * clear: fill the viewport's background too (1) or not (0, default). */
TISSUE_C_API int tissue_scene_set_host_depth(tissue_scene* scene, int share_depth, int clear);
/* A frame budget, ms (>= 0; 0: off, the default): each render then lets the quality controller
 * choose every organ's method and setting from its footprint, distance, view angle and motion so
 * that the frame fits, learning the costs from the measured passes (issue 16). */
TISSUE_C_API int tissue_scene_set_budget_ms(tissue_scene* scene, double budget_ms);
/* Under a budget, each organ's method settings (CPU fits, up to ~0.1 s each) are built on a worker
 * thread and offered to the controller as they are ready, so no frame waits for one. This waits
 * until all are built (a loading screen; not for the frame path). *pending (may be NULL): how
 * many were still being built when it was called. */
TISSUE_C_API int tissue_scene_prepare_budget_options(tissue_scene* scene, long* pending);
/* What the controller chose for the organ at the last render, "<method> <setting>" (e.g.
 * "lit wrap", "ray-march 10"), NUL-terminated into text (size bytes); "" while the budget is off. */
TISSUE_C_API int tissue_organ_chosen_method(const tissue_organ* organ, char* text, int size);
/* Renders into the scene's own target and writes a PNG (atomically). */
TISSUE_C_API int tissue_scene_render_png(tissue_scene* scene, const char* path, int width, int height);

#ifdef __cplusplus
}
#endif

#endif /* TISSUE_TISSUE_C_H */
