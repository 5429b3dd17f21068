// Scenario files: JSON -> Scenario, every error naming the file and the key (docs/SCENARIOS.md).
#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <string>

#include "tissue/core/atomic_file.h"
#include "tissue/scenario/scenario.h"

namespace tissue::scenario {
namespace {

using nlohmann::json;

/// A bad key, thrown inside the parser only and turned into an Error before returning.
struct KeyError {
  std::string key, what;
};

std::string shown(const json& v) {
  std::string s = v.dump();
  return s.size() > 60 ? s.substr(0, 57) + "..." : s;
}

std::string join(const std::string& prefix, const std::string& key) {
  return prefix.empty() ? key : prefix + "." + key;
}

/// Every key of `obj` must be in `allowed`; `obj` itself must be an object.
void checkObject(const json& obj, const std::string& where, std::initializer_list<const char*> allowed) {
  if (!obj.is_object())
    throw KeyError{where.empty() ? "(top level)" : where, "expected an object, got " + shown(obj)};
  for (const auto& [key, value] : obj.items()) {
    // key by an init-capture: clang 14 (the fuzz tree's compiler) cannot capture a structured binding.
    const bool known =
        std::any_of(allowed.begin(), allowed.end(), [&name = key](const char* a) { return name == a; });
    if (known) continue;
    std::string list;
    for (const char* a : allowed)
      list += std::string(list.empty() ? "" : ", ") + a;
    throw KeyError{join(where, key), "unknown key; the keys here are " + list};
  }
}

double number(const json& v, const std::string& key, const std::string& unit) {
  if (!v.is_number() || !std::isfinite(v.get<double>()))
    throw KeyError{key, "expected a number (" + unit + "), got " + shown(v)};
  return v.get<double>();
}

double positive(const json& v, const std::string& key, const std::string& unit) {
  const double x = v.is_number() ? v.get<double>() : -1.0;
  if (!v.is_number() || !(x > 0.0) || !std::isfinite(x))
    throw KeyError{key, "expected a positive number (" + unit + "), got " + shown(v)};
  return x;
}

double nonNegative(const json& v, const std::string& key, const std::string& unit) {
  const double x = v.is_number() ? v.get<double>() : -1.0;
  if (!v.is_number() || !(x >= 0.0) || !std::isfinite(x))
    throw KeyError{key, "expected a number >= 0 (" + unit + "), got " + shown(v)};
  return x;
}

int positiveInt(const json& v, const std::string& key) {
  if (!v.is_number_integer() || v.get<long long>() < 1 || v.get<long long>() > 100000000)
    throw KeyError{key, "expected a positive integer, got " + shown(v)};
  return static_cast<int>(v.get<long long>());
}

std::string text(const json& v, const std::string& key, std::initializer_list<const char*> choices) {
  std::string list;
  for (const char* c : choices)
    list += std::string(list.empty() ? "" : ", ") + "\"" + c + "\"";
  if (!v.is_string() || std::none_of(choices.begin(), choices.end(), [&](const char* c) { return v == c; }))
    throw KeyError{key, "expected one of " + list + ", got " + shown(v)};
  return v.get<std::string>();
}

sim::Vec3d vec3(const json& v, const std::string& key, const std::string& unit) {
  if (!v.is_array() || v.size() != 3)
    throw KeyError{key, "expected [x, y, z] (" + unit + "), got " + shown(v)};
  return {number(v[0], key + "[0]", unit), number(v[1], key + "[1]", unit), number(v[2], key + "[2]", unit)};
}

std::filesystem::path resolveMesh(const json& v, const std::filesystem::path& file,
                                  const ScenarioPaths& paths) {
  if (!v.is_string() || v.get<std::string>().empty())
    throw KeyError{"mesh", "expected a path to a mesh file, got " + shown(v)};
  const std::filesystem::path p = v.get<std::string>();
  if (p.is_absolute()) {
    if (!std::filesystem::exists(p)) throw KeyError{"mesh", "no file " + p.string()};
    return p;
  }
  const auto local = file.parent_path() / p;
  if (std::filesystem::exists(local)) return local;
  if (!paths.sharedMeshesDir.empty() && std::filesystem::exists(paths.sharedMeshesDir / p))
    return paths.sharedMeshesDir / p;
  throw KeyError{"mesh",
                 "no file " + local.string() +
                     (paths.sharedMeshesDir.empty() ? "" : " nor " + (paths.sharedMeshesDir / p).string()) +
                     "; paths are relative to the scenario's folder or to the shared meshes"};
}

void parseSprings(const json& s, bool tissue, Scenario& out) {
  checkObject(s, "springs", {"from", "stiffness", "stiffness_law", "bending_stiffness"});
  if (!s.contains("from"))
    throw KeyError{"springs.from", "missing; give \"surface\", \"tet-edges\" or \"lattice\""};
  const std::string from = text(s["from"], "springs.from", {"surface", "tet-edges", "lattice"});
  out.springSource = from == "surface"     ? SpringSource::Surface
                     : from == "tet-edges" ? SpringSource::TetEdges
                                           : SpringSource::Lattice;
  if (tissue) {  // the stiffness comes from the tissue block's material constants
    for (const char* key : {"stiffness", "stiffness_law", "bending_stiffness"})
      if (s.contains(key))
        throw KeyError{std::string("springs.") + key,
                       "give either springs." + std::string(key) +
                           " (per-spring values) or the tissue block (material constants), not both"};
    return;
  }
  std::string law = "constant";
  if (s.contains("stiffness_law"))
    law = text(s["stiffness_law"], "springs.stiffness_law", {"constant", "per-rest-length"});
  out.springs.law = law == "constant" ? sim::StiffnessLaw::Constant : sim::StiffnessLaw::PerRestLength;
  const std::string unit = law == "constant" ? "N/mm" : "N";
  if (!s.contains("stiffness"))
    throw KeyError{"springs.stiffness", "missing; give a positive number (" + unit +
                                            "), or a tissue block {\"youngs_modulus_kpa\": kPa}"};
  out.springs.stiffness = positive(s["stiffness"], "springs.stiffness", unit);
  if (s.contains("bending_stiffness"))
    out.springs.bendingStiffness = nonNegative(s["bending_stiffness"], "springs.bending_stiffness", unit);
}

/// The tissue block: E (kPa, required), nu, density (g/mm^3), thickness (mm) and bending fraction
/// (surface only).
void parseTissue(const json& t, Scenario& out) {
  checkObject(
      t, "tissue",
      {"youngs_modulus_kpa", "poisson_ratio", "density_g_per_mm3", "thickness_mm", "bending_fraction"});
  TissueSpec spec;
  if (!t.contains("youngs_modulus_kpa"))
    throw KeyError{"tissue.youngs_modulus_kpa", "missing; give Young's modulus in kPa (liver about 5)"};
  spec.material.youngsModulusKpa = positive(t["youngs_modulus_kpa"], "tissue.youngs_modulus_kpa", "kPa");
  if (t.contains("poisson_ratio")) {
    const json& v = t["poisson_ratio"];
    const double nu = v.is_number() ? v.get<double>() : -1.0;
    if (!v.is_number() || !(nu > 0.0 && nu < 0.5))
      throw KeyError{
          "tissue.poisson_ratio",
          "expected a number in (0, 0.5) (0.5, incompressible, is not reachable), got " + shown(v)};
    spec.material.poissonRatio = nu;
    if (nu != sim::kEffectivePoissonRatio)
      out.warnings.push_back(out.file.string() + ": tissue.poisson_ratio: " + shown(v) +
                             " is reported but not realised; the springs' effective Poisson's ratio is 0.25 "
                             "(central forces, the Cauchy relation)");
  }
  if (t.contains("density_g_per_mm3"))
    spec.material.densityGPerMm3 = positive(t["density_g_per_mm3"], "tissue.density_g_per_mm3", "g/mm^3");
  const bool surface = out.springSource == SpringSource::Surface;
  for (const char* key : {"thickness_mm", "bending_fraction"})
    if (t.contains(key) && !surface)
      throw KeyError{std::string("tissue.") + key,
                     "only for springs.from = \"surface\" (a shell); a volume needs no thickness"};
  if (t.contains("thickness_mm"))
    spec.shell.thicknessMm = positive(t["thickness_mm"], "tissue.thickness_mm", "mm");
  if (t.contains("bending_fraction"))
    spec.shell.bendingFraction =
        nonNegative(t["bending_fraction"], "tissue.bending_fraction", "fraction of the edge spring");
  out.tissue = spec;
}

/// Without a mass key, the tissue's density: per volume, or times the shell's thickness per area.
void massFromTissue(Scenario& out) {
  out.mass.total = 0.0;
  if (out.springSource == SpringSource::Surface)
    out.mass.arealDensity = out.tissue->material.densityGPerMm3 * out.tissue->shell.thicknessMm;
  else
    out.massVolumeDensity = out.tissue->material.densityGPerMm3;
}

void parseMass(const json& m, Scenario& out) {
  checkObject(m, "mass", {"total", "density", "distribution"});
  if (out.tissue && !m.contains("total") && !m.contains("density")) {
    massFromTissue(out);  // e.g. {"distribution": "uniform"} with the tissue's density
  } else if (m.contains("total") == m.contains("density")) {
    throw KeyError{"mass",
                   "give exactly one of total (g) and density (g/mm^2 for surface springs, g/mm^3 for "
                   "tet-edges and lattice)"};
  }
  const bool volume = out.springSource != SpringSource::Surface;
  out.mass.total = m.contains("total") ? positive(m["total"], "mass.total", "g") : 0.0;
  if (m.contains("density")) {
    const double d = positive(m["density"], "mass.density", volume ? "g/mm^3" : "g/mm^2");
    (volume ? out.massVolumeDensity : out.mass.arealDensity) = d;
  }
  if (m.contains("distribution"))
    out.mass.distribution = text(m["distribution"], "mass.distribution", {"uniform", "lumped"}) == "uniform"
                                ? sim::MassDistribution::Uniform
                                : sim::MassDistribution::Lumped;
}

void parseDamping(const json& d, Scenario& out) {
  if (d.is_number()) {
    out.springs.damping = nonNegative(d, "damping", "N*s/mm");
    return;
  }
  checkObject(d, "damping", {"springs", "rayleigh_mass", "rayleigh_stiffness"});
  if (d.contains("springs")) out.springs.damping = nonNegative(d["springs"], "damping.springs", "N*s/mm");
  if (d.contains("rayleigh_mass"))
    out.system.rayleighMass = nonNegative(d["rayleigh_mass"], "damping.rayleigh_mass", "1/s");
  if (d.contains("rayleigh_stiffness"))
    out.system.rayleighStiffness = nonNegative(d["rayleigh_stiffness"], "damping.rayleigh_stiffness", "s");
}

void parsePinned(const json& p, Scenario& out) {
  if (p.is_array()) {
    for (std::size_t k = 0; k < p.size(); ++k) {
      const std::string key = "pinned[" + std::to_string(k) + "]";
      if (!p[k].is_number_integer() || p[k].get<long long>() < 0 || p[k].get<long long>() > 0xFFFFFFFFll)
        throw KeyError{key, "expected a vertex index (0-based, file order), got " + shown(p[k])};
      out.pinnedIndices.push_back(static_cast<std::uint32_t>(p[k].get<long long>()));
    }
    return;
  }
  checkObject(p, "pinned", {"axis", "below"});
  if (!p.contains("axis") || !p.contains("below"))
    throw KeyError{"pinned",
                   "give a list of vertex indices, or {\"axis\": \"x\"|\"y\"|\"z\", \"below\": mm}"};
  const std::string axis = text(p["axis"], "pinned.axis", {"x", "y", "z"});
  out.pinnedRegion = PinRegion{axis == "x"   ? 0
                               : axis == "y" ? 1
                                             : 2,
                               number(p["below"], "pinned.below", "mm")};
}

void parseSolver(const json& s, Scenario& out) {
  checkObject(s, "solver", {"max_iterations", "tolerance"});
  if (s.contains("max_iterations"))
    out.solver.maxIterations = positiveInt(s["max_iterations"], "solver.max_iterations");
  if (s.contains("tolerance"))
    out.solver.relativeTolerance = positive(s["tolerance"], "solver.tolerance", "relative");
}

sim::ToolKeyframe parseKeyframe(const json& k, const std::string& key, const sim::Vec3d& defaultAxis) {
  checkObject(k, key, {"time", "position", "axis"});
  if (!k.contains("time") || !k.contains("position"))
    throw KeyError{key, "a keyframe needs \"time\" (s) and \"position\" ([x, y, z] mm)"};
  sim::ToolKeyframe f{number(k["time"], key + ".time", "s"),
                      {vec3(k["position"], key + ".position", "mm"), defaultAxis}};
  if (k.contains("axis")) f.pose.axis = vec3(k["axis"], key + ".axis", "direction");
  if (!(sim::length(f.pose.axis) > 0.0)) throw KeyError{key + ".axis", "expected a non-zero direction"};
  return f;
}

void parseInstrument(const json& j, Scenario& out) {
  checkObject(j, "instrument",
              {"shape", "radius", "length", "axis", "path", "actions", "max_sub_move", "grasp_margin"});
  InstrumentSpec spec;
  if (!j.contains("shape")) throw KeyError{"instrument.shape", "missing; give \"sphere\" or \"capsule\""};
  const bool capsule = text(j["shape"], "instrument.shape", {"sphere", "capsule"}) == "capsule";
  spec.config.shape.kind = capsule ? sim::ToolShapeKind::Capsule : sim::ToolShapeKind::Sphere;
  if (!j.contains("radius")) throw KeyError{"instrument.radius", "missing; give a positive number (mm)"};
  spec.config.shape.radius = positive(j["radius"], "instrument.radius", "mm");
  if (j.contains("length")) {
    if (!capsule)
      throw KeyError{"instrument.length", "only a capsule has a length; remove it or use \"capsule\""};
    spec.config.shape.length = nonNegative(j["length"], "instrument.length", "mm");
  } else if (capsule) {
    throw KeyError{"instrument.length", "missing; a capsule needs its length (mm, between the cap centres)"};
  }
  sim::Vec3d axis{0.0, 0.0, 1.0};
  if (j.contains("axis")) axis = vec3(j["axis"], "instrument.axis", "direction");
  if (!(sim::length(axis) > 0.0)) throw KeyError{"instrument.axis", "expected a non-zero direction"};
  if (j.contains("max_sub_move")) {
    const double f = positive(j["max_sub_move"], "instrument.max_sub_move", "fraction of the radius");
    if (f > 1.0)
      throw KeyError{"instrument.max_sub_move",
                     "expected a fraction of the radius in (0, 1], got " + shown(j["max_sub_move"])};
    spec.config.maxSubMoveFraction = f;
  }
  if (j.contains("grasp_margin"))
    spec.config.graspMarginMm = nonNegative(j["grasp_margin"], "instrument.grasp_margin", "mm");
  if (!j.contains("path") || !j["path"].is_array() || j["path"].empty())
    throw KeyError{"instrument.path",
                   "expected a list of keyframes {\"time\": s, \"position\": [x, y, z] mm}"};
  for (std::size_t k = 0; k < j["path"].size(); ++k) {
    const std::string key = "instrument.path[" + std::to_string(k) + "]";
    spec.path.push_back(parseKeyframe(j["path"][k], key, axis));
    if (k > 0 && !(spec.path[k].time > spec.path[k - 1].time))
      throw KeyError{key + ".time", "keyframe times must increase; got " + shown(j["path"][k]["time"]) +
                                        " after " + shown(j["path"][k - 1]["time"])};
  }
  if (j.contains("actions")) {
    if (!j["actions"].is_array())
      throw KeyError{"instrument.actions", "expected a list of {\"time\": s, \"action\": ...}"};
    for (std::size_t k = 0; k < j["actions"].size(); ++k) {
      const std::string key = "instrument.actions[" + std::to_string(k) + "]";
      const json& a = j["actions"][k];
      checkObject(a, key, {"time", "action"});
      if (!a.contains("time") || !a.contains("action"))
        throw KeyError{key, "an action needs \"time\" (s) and \"action\" (\"grasp\" or \"release\")"};
      spec.actions.push_back({number(a["time"], key + ".time", "s"),
                              text(a["action"], key + ".action", {"grasp", "release"}) == "grasp"});
    }
    std::stable_sort(spec.actions.begin(), spec.actions.end(),
                     [](const auto& a, const auto& b) { return a.time < b.time; });
  }
  out.instrument = std::move(spec);
}

void parseTopLevel(const json& j, const std::filesystem::path& file, const ScenarioPaths& paths,
                   Scenario& out) {
  checkObject(j, "",
              {"description", "mesh", "mesh_scale_to_mm", "springs", "tissue", "lattice", "mass", "damping",
               "gravity", "pinned", "integrator", "dt", "substeps", "frames", "solver", "instrument"});
  if (j.contains("description") && !j["description"].is_string())
    throw KeyError{"description", "expected a string, got " + shown(j["description"])};
  if (!j.contains("mesh")) throw KeyError{"mesh", "missing; give the path of the mesh"};
  out.mesh = resolveMesh(j["mesh"], file, paths);
  if (j.contains("mesh_scale_to_mm"))
    out.meshScaleToMm = positive(j["mesh_scale_to_mm"], "mesh_scale_to_mm", "mm per file unit");
  if (!j.contains("springs"))
    throw KeyError{"springs", "missing; give {\"from\": \"surface\", \"stiffness\": N/mm}"};
  parseSprings(j["springs"], j.contains("tissue"), out);
  if (j.contains("tissue")) parseTissue(j["tissue"], out);
  if (j.contains("lattice")) {
    if (out.springSource != SpringSource::Lattice)
      throw KeyError{"lattice", "only used with springs.from = \"lattice\""};
    checkObject(j["lattice"], "lattice", {"cell_size"});
    if (!j["lattice"].contains("cell_size"))
      throw KeyError{"lattice.cell_size", "missing; give a positive number (mm)"};
    out.latticeCellSizeMm = positive(j["lattice"]["cell_size"], "lattice.cell_size", "mm");
  } else if (out.springSource == SpringSource::Lattice) {
    throw KeyError{"lattice", "missing; springs.from = \"lattice\" needs {\"cell_size\": mm}"};
  }
  if (j.contains("mass"))
    parseMass(j["mass"], out);
  else if (out.tissue)
    massFromTissue(out);
  else
    throw KeyError{"mass", "missing; give {\"total\": g} or {\"density\": ...}, or a tissue block"};
  if (j.contains("damping")) parseDamping(j["damping"], out);
  if (j.contains("gravity")) out.system.gravity = vec3(j["gravity"], "gravity", "mm/s^2");
  if (j.contains("pinned")) parsePinned(j["pinned"], out);
  if (j.contains("integrator")) {
    const std::string name =
        text(j["integrator"], "integrator",
             {"explicit-euler", "symplectic-euler", "verlet", "implicit-euler", "fast-mass-spring"});
    out.integrator = *sim::parseIntegrator(name);
  }
  if (j.contains("dt")) out.frameTime = positive(j["dt"], "dt", "s per frame");
  if (j.contains("substeps")) out.substeps = positiveInt(j["substeps"], "substeps");
  if (out.substeps > 64)
    throw KeyError{"substeps", "at most 64 (the divergence recovery doubles them up to 64)"};
  if (j.contains("frames")) out.frames = positiveInt(j["frames"], "frames");
  if (j.contains("solver")) parseSolver(j["solver"], out);
  if (j.contains("instrument")) parseInstrument(j["instrument"], out);
}

}  // namespace

Result<Scenario> parseScenario(const std::string& text, const std::filesystem::path& file,
                               const ScenarioPaths& paths) {
  const std::string name = file.string();
  json j;
  try {
    j = json::parse(text);
  } catch (const json::exception& e) {  // parse errors, and numbers beyond a double (out_of_range.406)
    return Error{name + ": not valid JSON (" + e.what() + ")"};
  }
  Scenario out;
  out.file = file;
  try {
    parseTopLevel(j, file, paths, out);
  } catch (const KeyError& e) {
    return Error{name + ": " + e.key + ": " + e.what};
  } catch (const json::exception& e) {  // a value of the wrong type where no check named its key
    return Error{name + ": a value has the wrong type (" + e.what() + "); see docs/DATA.md for the schema"};
  }
  return out;
}

Result<Scenario> loadScenario(const std::filesystem::path& file, const ScenarioPaths& paths) {
  auto text = readTextFile(file);
  if (!text) return text.error();
  return parseScenario(*text, file, paths);
}

}  // namespace tissue::scenario
