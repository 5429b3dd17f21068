// The C API (tissue/tissue_c.h) over tissue::scene::Scene: handles, codes, the thread's last
// error. Every entry point catches everything: no exception crosses the C boundary.
#include "tissue/tissue_c.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "tissue/scene/scene.h"

struct tissue_organ {
  tissue_scene* scene = nullptr;
  tissue::scene::OrganId id = 0;
};

struct tissue_scene {
  std::optional<tissue::scene::Scene> scene;
  std::vector<std::unique_ptr<tissue_organ>> organs;
  tissue::render::HostFramebuffer host;  ///< depth and clear choices for tissue_scene_render
  tissue::render::Camera camera;         ///< clip distances, and the fixed camera once set
  bool cameraSet = false;
};

namespace {

thread_local std::string g_lastError;  // per thread, as the header promises

int fail(int code, std::string message) {
  g_lastError = std::move(message);
  return code;
}

/// Runs `body`, turning an escaping exception into TISSUE_ERROR_INTERNAL with its message.
template <typename F>
int guarded(const char* function, F&& body) {
  try {
    return body();
  } catch (const std::exception& e) {
    return fail(TISSUE_ERROR_INTERNAL, std::string(function) + ": " + e.what());
  } catch (...) {
    return fail(TISSUE_ERROR_INTERNAL, std::string(function) + ": unknown failure");
  }
}

int fromResult(const tissue::Result<void>& r, int code) {
  return r ? TISSUE_OK : fail(code, r.error().message);
}

}  // namespace

extern "C" {

const char* tissue_last_error(void) {
  return g_lastError.c_str();
}

int tissue_scene_create(void* (*get_proc_address)(const char*), tissue_scene** out) {
  return guarded("tissue_scene_create", [&] {
    if (!out) return fail(TISSUE_ERROR_ARGUMENT, "tissue_scene_create: out is NULL");
    *out = nullptr;
    tissue::gl::GetProcAddressFn lookup;
    if (get_proc_address)
      lookup = [get_proc_address](const char* name) {
        return reinterpret_cast<tissue::gl::GlProc>(get_proc_address(name));
      };
    auto scene = tissue::scene::Scene::create(lookup);
    if (!scene) return fail(TISSUE_ERROR_GL, "tissue_scene_create: " + scene.error().message);
    auto handle = std::make_unique<tissue_scene>();
    handle->scene.emplace(std::move(*scene));
    handle->host.depth = tissue::render::HostDepth::TestAndWrite;
    handle->host.clear = false;
    *out = handle.release();
    return TISSUE_OK;
  });
}

void tissue_scene_destroy(tissue_scene* scene) {
  (void)guarded("tissue_scene_destroy", [&] {
    delete scene;
    return TISSUE_OK;
  });
}

int tissue_organ_add(tissue_scene* scene, const char* mesh_path, const char* material_path,
                     const char* scenario_path_or_null, tissue_organ** out) {
  return guarded("tissue_organ_add", [&] {
    if (!scene || !out) return fail(TISSUE_ERROR_ARGUMENT, "tissue_organ_add: scene or out is NULL");
    *out = nullptr;
    if (!mesh_path && !scenario_path_or_null)
      return fail(TISSUE_ERROR_ARGUMENT,
                  "tissue_organ_add: give mesh_path, or a scenario that names the mesh");
    tissue::scene::OrganDesc desc;
    if (mesh_path) desc.mesh = mesh_path;
    if (material_path) desc.material = material_path;
    if (scenario_path_or_null) desc.scenario = scenario_path_or_null;
    auto id = scene->scene->addOrgan(desc);
    if (!id) return fail(TISSUE_ERROR_FILE, "tissue_organ_add: " + id.error().message);
    auto organ = std::make_unique<tissue_organ>();
    organ->scene = scene;
    organ->id = *id;
    *out = organ.get();
    scene->organs.push_back(std::move(organ));
    return TISSUE_OK;
  });
}

int tissue_organ_set_method(tissue_organ* organ, const char* method) {
  return guarded("tissue_organ_set_method", [&] {
    if (!organ || !method)
      return fail(TISSUE_ERROR_ARGUMENT, "tissue_organ_set_method: organ or method is NULL");
    auto m = tissue::scene::parseShadingMethod(method);
    if (!m) return fail(TISSUE_ERROR_ARGUMENT, "tissue_organ_set_method: " + m.error().message);
    return fromResult(organ->scene->scene->setMethod(organ->id, *m), TISSUE_ERROR_ARGUMENT);
  });
}

int tissue_scene_set_budget_ms(tissue_scene* scene, double budget_ms) {
  return guarded("tissue_scene_set_budget_ms", [&] {
    if (!scene) return fail(TISSUE_ERROR_ARGUMENT, "tissue_scene_set_budget_ms: scene is NULL");
    auto r = scene->scene->setBudgetMs(budget_ms);
    return r ? TISSUE_OK : fail(TISSUE_ERROR_ARGUMENT, "tissue_scene_set_budget_ms: " + r.error().message);
  });
}

int tissue_scene_prepare_budget_options(tissue_scene* scene, long* pending) {
  return guarded("tissue_scene_prepare_budget_options", [&] {
    if (!scene) return fail(TISSUE_ERROR_ARGUMENT, "tissue_scene_prepare_budget_options: scene is NULL");
    if (pending) *pending = long(scene->scene->budgetOptionsPending());
    auto r = scene->scene->prepareBudgetOptions();
    return r ? TISSUE_OK
             : fail(TISSUE_ERROR_ARGUMENT, "tissue_scene_prepare_budget_options: " + r.error().message);
  });
}

int tissue_organ_chosen_method(const tissue_organ* organ, char* text, int size) {
  return guarded("tissue_organ_chosen_method", [&] {
    if (!organ || !text || size <= 0)
      return fail(TISSUE_ERROR_ARGUMENT, "tissue_organ_chosen_method: organ or text is NULL, or size <= 0");
    const auto& choices = organ->scene->scene->budgetChoices();
    const std::string chosen = organ->id < choices.size()
                                   ? choices[organ->id].method + " " + choices[organ->id].setting
                                   : std::string();
    if (chosen.size() + 1 > std::size_t(size))
      return fail(TISSUE_ERROR_ARGUMENT, "tissue_organ_chosen_method: give at least " +
                                             std::to_string(chosen.size() + 1) + " bytes");
    std::copy(chosen.begin(), chosen.end(), text);
    text[chosen.size()] = '\0';
    return TISSUE_OK;
  });
}

int tissue_organ_set_transform(tissue_organ* organ, const float model[16]) {
  return guarded("tissue_organ_set_transform", [&] {
    if (!organ || !model)
      return fail(TISSUE_ERROR_ARGUMENT, "tissue_organ_set_transform: organ or model is NULL");
    tissue::Mat4 m;
    std::copy(model, model + 16, m.begin());
    auto r = organ->scene->scene->setTransform(organ->id, m);
    return r ? TISSUE_OK : fail(TISSUE_ERROR_ARGUMENT, "tissue_organ_set_transform: " + r.error().message);
  });
}

int tissue_instrument_set_pose(tissue_scene* scene, float x_mm, float y_mm, float z_mm, float radius_mm) {
  return guarded("tissue_instrument_set_pose", [&] {
    if (!scene) return fail(TISSUE_ERROR_ARGUMENT, "tissue_instrument_set_pose: scene is NULL");
    tissue::scene::InstrumentPose pose;
    pose.tipMm = {x_mm, y_mm, z_mm};
    pose.radiusMm = radius_mm;
    auto r = scene->scene->setInstrumentPose(pose);
    return r ? TISSUE_OK : fail(TISSUE_ERROR_ARGUMENT, "tissue_instrument_set_pose: " + r.error().message);
  });
}

int tissue_instrument_grasp(tissue_scene* scene, int grasp) {
  return guarded("tissue_instrument_grasp", [&] {
    if (!scene) return fail(TISSUE_ERROR_ARGUMENT, "tissue_instrument_grasp: scene is NULL");
    return fromResult(scene->scene->setGrasp(grasp != 0), TISSUE_ERROR_ARGUMENT);
  });
}

int tissue_instrument_force(const tissue_scene* scene, float force_N[3]) {
  return guarded("tissue_instrument_force", [&] {
    if (!scene || !force_N)
      return fail(TISSUE_ERROR_ARGUMENT, "tissue_instrument_force: scene or force_N is NULL");
    const tissue::Float3 f = scene->scene->instrumentForceN();
    force_N[0] = f.x, force_N[1] = f.y, force_N[2] = f.z;
    return TISSUE_OK;
  });
}

int tissue_instrument_set_visible(tissue_scene* scene, int visible) {
  return guarded("tissue_instrument_set_visible", [&] {
    if (!scene) return fail(TISSUE_ERROR_ARGUMENT, "tissue_instrument_set_visible: scene is NULL");
    scene->scene->setInstrumentVisible(visible != 0);
    return TISSUE_OK;
  });
}

int tissue_scene_set_camera(tissue_scene* scene, const float eye[3], const float target[3], const float up[3],
                            float fov_y_deg) {
  return guarded("tissue_scene_set_camera", [&] {
    if (!scene || !eye || !target || !up)
      return fail(TISSUE_ERROR_ARGUMENT, "tissue_scene_set_camera: a NULL argument");
    if (!(fov_y_deg > 0.0f && fov_y_deg < 180.0f))
      return fail(TISSUE_ERROR_ARGUMENT, "tissue_scene_set_camera: fov_y_deg must lie in (0, 180) degrees");
    auto& c = scene->camera;
    c.eye = {eye[0], eye[1], eye[2]};
    c.target = {target[0], target[1], target[2]};
    c.up = {up[0], up[1], up[2]};
    c.verticalFovDeg = fov_y_deg;
    if (!tissue::isFinite(c.eye) || !tissue::isFinite(c.target) || !tissue::isFinite(c.up) ||
        tissue::length(c.target - c.eye) <= 0.0f ||
        tissue::length(tissue::cross(c.target - c.eye, c.up)) <= 0.0f)
      return fail(
          TISSUE_ERROR_ARGUMENT,
          "tissue_scene_set_camera: eye and target must differ and up must not be parallel to the view");
    scene->cameraSet = true;
    scene->scene->setCamera(c);
    return TISSUE_OK;
  });
}

int tissue_scene_set_clip(tissue_scene* scene, float near_mm, float far_mm) {
  return guarded("tissue_scene_set_clip", [&] {
    if (!scene) return fail(TISSUE_ERROR_ARGUMENT, "tissue_scene_set_clip: scene is NULL");
    if (!(near_mm > 0.0f) || !(far_mm > near_mm) || !std::isfinite(far_mm))
      return fail(TISSUE_ERROR_ARGUMENT, "tissue_scene_set_clip: need 0 < near_mm < far_mm (mm)");
    scene->camera.nearMm = near_mm;
    scene->camera.farMm = far_mm;
    if (scene->cameraSet) scene->scene->setCamera(scene->camera);
    return TISSUE_OK;
  });
}

int tissue_scene_step(tissue_scene* scene, double dt_s) {
  return guarded("tissue_scene_step", [&] {
    if (!scene) return fail(TISSUE_ERROR_ARGUMENT, "tissue_scene_step: scene is NULL");
    auto r = scene->scene->step(dt_s);
    return r ? TISSUE_OK : fail(TISSUE_ERROR_ARGUMENT, "tissue_scene_step: " + r.error().message);
  });
}

int tissue_scene_set_host_depth(tissue_scene* scene, int share_depth, int clear) {
  return guarded("tissue_scene_set_host_depth", [&] {
    if (!scene) return fail(TISSUE_ERROR_ARGUMENT, "tissue_scene_set_host_depth: scene is NULL");
    scene->host.depth =
        share_depth ? tissue::render::HostDepth::TestAndWrite : tissue::render::HostDepth::Ignore;
    scene->host.clear = clear != 0;
    return TISSUE_OK;
  });
}

int tissue_scene_render(tissue_scene* scene, unsigned int framebuffer, int width, int height) {
  return guarded("tissue_scene_render", [&] {
    if (!scene) return fail(TISSUE_ERROR_ARGUMENT, "tissue_scene_render: scene is NULL");
    if (width <= 0 || height <= 0)
      return fail(TISSUE_ERROR_ARGUMENT, "tissue_scene_render: width and height must be positive pixels");
    tissue::render::HostFramebuffer target = scene->host;
    target.framebuffer = framebuffer;
    target.width = width;
    target.height = height;
    auto r = scene->scene->render(target);
    return r ? TISSUE_OK : fail(TISSUE_ERROR_GL, "tissue_scene_render: " + r.error().message);
  });
}

int tissue_scene_render_png(tissue_scene* scene, const char* path, int width, int height) {
  return guarded("tissue_scene_render_png", [&] {
    if (!scene || !path) return fail(TISSUE_ERROR_ARGUMENT, "tissue_scene_render_png: scene or path is NULL");
    if (width <= 0 || height <= 0 || width > 16384 || height > 16384)
      return fail(TISSUE_ERROR_ARGUMENT, "tissue_scene_render_png: width and height must be 1..16384 pixels");
    auto r = scene->scene->renderPng(path, width, height);
    return r ? TISSUE_OK : fail(TISSUE_ERROR_FILE, "tissue_scene_render_png: " + r.error().message);
  });
}

}  // extern "C"
