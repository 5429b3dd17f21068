#pragma once
/// \file
/// The umbrella header of tissue (target tissue::tissue): the public API a host uses to embed the
/// library, in the order of a frame's data flow (docs/ARCHITECTURE.md). Each header also stands
/// alone; a host that wants less includes only those it needs. No header here includes a
/// third-party header (no OpenMesh, Eigen, VTK, glad or GL): tissue speaks plain arrays
/// (tissue/core/types.h, units in mm, g, s, N) and Results (tissue/core/result.h).
///
///   find_package(tissue 0.1 REQUIRED)
///   target_link_libraries(app PRIVATE tissue::tissue)
///
/// Left out on purpose: the GLFW window backend (tissue/context/glfw_context.h, target
/// tissue::context_glfw, for hosts that open a window through tissue), and the internal GL
/// headers of the renderer (tissue/gl/gl_api.h, objects.h, program.h, not installed).

// Plain types, errors, images, timing.
#include "tissue/core/atomic_file.h"
#include "tissue/core/image.h"
#include "tissue/core/result.h"
#include "tissue/core/statistics.h"
#include "tissue/core/stopwatch.h"
#include "tissue/core/surface_mesh.h"
#include "tissue/core/types.h"
#include "tissue/core/vec_math.h"

// Meshes: loading (OBJ/PLY/OFF/STL), normals, tangent frames, local planes, the deforming surface;
// tetrahedral volume meshes (.msh; .vtk/.vtu with VTK).
#include "tissue/mesh/deformable_surface.h"
#include "tissue/mesh/load_mesh.h"
#include "tissue/mesh/local_planes.h"
#include "tissue/mesh/tangent_frames.h"
#include "tissue/mesh/uv_atlas.h"
#include "tissue/mesh/vertex_normals.h"
#include "tissue/volume/tet_mesh.h"

// Simulation: the mass-spring simulator, the instrument, scenario files and their runs.
#include "tissue/scenario/organ_stability.h"
#include "tissue/scenario/scenario.h"
#include "tissue/scenario/scenario_run.h"
#include "tissue/sim/instrument.h"
#include "tissue/sim/simulator.h"

// Optics and the materials of the shading methods.
#include "tissue/materials/method_materials.h"
#include "tissue/materials/raymarch_material.h"
#include "tissue/optics/kernel.h"
#include "tissue/optics/materials.h"
#include "tissue/subsurface/layer_stack.h"

// The path-traced truth: random-walk Monte Carlo in the layered organ, the references it is tested on.
#include "tissue/truth/material.h"
#include "tissue/truth/path_tracer.h"
#include "tissue/truth/ray_mesh.h"
#include "tissue/truth/slab_reference.h"

// The quality controller: each object's method and setting under a frame budget.
#include "tissue/quality/controller.h"
#include "tissue/quality/quality_table.h"

// Rendering: headless GL contexts (EGL, OSMesa), the renderer, its scene and shading methods.
#include "tissue/context/gl_context.h"
#include "tissue/context/headless_context.h"
#include "tissue/gl/proc_address.h"
#include "tissue/gl/shader_library.h"
#include "tissue/render/handles.h"
#include "tissue/render/renderer.h"
#include "tissue/render/scene.h"
#include "tissue/render/shading.h"

// The scene a host embeds (organs from mesh + material + scenario, the instrument, render into the
// host framebuffer), its per-frame loop (simulate -> mesh -> upload -> render) and recorded sessions.
#include "tissue/scene/budget.h"
#include "tissue/scene/instrument_mesh.h"
#include "tissue/scene/material_file.h"
#include "tissue/scene/organ_assets.h"
#include "tissue/scene/organ_loop.h"
#include "tissue/scene/organ_methods.h"
#include "tissue/scene/scene.h"
#include "tissue/scene/session.h"
#include "tissue/scene/surface_inspection.h"

// Inspection: .vtp exports and charts (an Error when tissue was built without VTK).
#include "tissue/inspect/chart.h"
#include "tissue/inspect/vtk_export.h"

// Studies: the computations behind the benchmarks and studies (errors against references,
// profile choice, re-fit comparisons), for hosts that measure as tissue-sim does.
#include "tissue/studies/coverage.h"
#include "tissue/studies/deformations.h"
#include "tissue/studies/indent_study.h"
#include "tissue/studies/kernel_report.h"
#include "tissue/studies/kernel_study.h"
#include "tissue/studies/organ_stability_report.h"
#include "tissue/studies/parallax_scene.h"
#include "tissue/studies/parallax_study.h"
#include "tissue/studies/profile_study.h"
#include "tissue/studies/raymarch_bench.h"
#include "tissue/studies/raymarch_scene.h"
#include "tissue/studies/raymarch_study.h"
#include "tissue/studies/refit_study.h"
#include "tissue/studies/report.h"
#include "tissue/studies/sim_bench.h"
#include "tissue/studies/spring_network_report.h"
#include "tissue/studies/sss_bench.h"
#include "tissue/studies/stability_report.h"
#include "tissue/studies/texture_space_organ.h"
#include "tissue/studies/tsd_bench.h"
#include "tissue/studies/tsd_error.h"
