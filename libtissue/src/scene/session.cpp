// Recorded sessions: JSON in and out, the replay input, and the positions fingerprint.
// nlohmann-json and OpenSSL's SHA-256 stay inside this file.
#include "tissue/scene/session.h"

#include <openssl/evp.h>

#include <cmath>
#include <cstring>
#include <nlohmann/json.hpp>

#include "tissue/core/atomic_file.h"

namespace tissue::scene {
namespace {

using json = nlohmann::json;

constexpr int kSessionVersion = 1;

/// A parse failure at a key ("frames[3].pose"), turned into one Error line by loadSession.
struct KeyError {
  std::string key, what;
};

Float3 float3(const json& j, const std::string& key, const char* unit) {
  if (!j.is_array() || j.size() != 3) throw KeyError{key, std::string("expected 3 numbers (") + unit + ")"};
  Float3 v{};
  float* out[3] = {&v.x, &v.y, &v.z};
  for (int i = 0; i < 3; ++i) {
    if (!j[i].is_number() || !std::isfinite(j[i].get<double>()))
      throw KeyError{key, std::string("expected 3 finite numbers (") + unit + ")"};
    *out[i] = j[i].get<float>();
  }
  return v;
}

json toJson(const Float3& v) {
  return json::array({v.x, v.y, v.z});
}
json toJson(const sim::Vec3d& v) {
  return json::array({v.x, v.y, v.z});
}

sim::Vec3d vec3d(const json& j, const std::string& key) {
  const Float3 check = float3(j, key, "mm");  // validates shape and finiteness
  (void)check;
  return {j[0].get<double>(), j[1].get<double>(), j[2].get<double>()};
}

render::Camera parseCamera(const json& j, const std::string& key) {
  if (!j.is_object()) throw KeyError{key, "expected {\"eye\", \"target\", \"up\", \"fov_y_deg\"}"};
  render::Camera c;
  for (const auto& [name, value] : j.items())
    if (name != "eye" && name != "target" && name != "up" && name != "fov_y_deg")
      throw KeyError{key + "." + name, "unknown key; use eye, target, up, fov_y_deg"};
  if (j.contains("eye")) c.eye = float3(j["eye"], key + ".eye", "mm");
  if (j.contains("target")) c.target = float3(j["target"], key + ".target", "mm");
  if (j.contains("up")) c.up = float3(j["up"], key + ".up", "direction");
  if (j.contains("fov_y_deg")) {
    if (!j["fov_y_deg"].is_number() || !(j["fov_y_deg"].get<double>() > 0.0) ||
        !(j["fov_y_deg"].get<double>() < 180.0))
      throw KeyError{key + ".fov_y_deg", "expected degrees in (0, 180)"};
    c.verticalFovDeg = j["fov_y_deg"].get<float>();
  }
  return c;
}

json cameraJson(const render::Camera& c) {
  return {{"eye", toJson(c.eye)},
          {"target", toJson(c.target)},
          {"up", toJson(c.up)},
          {"fov_y_deg", c.verticalFovDeg}};
}

bool sameCamera(const render::Camera& a, const render::Camera& b) {
  return std::memcmp(&a.eye, &b.eye, sizeof(Float3)) == 0 &&
         std::memcmp(&a.target, &b.target, sizeof(Float3)) == 0 &&
         std::memcmp(&a.up, &b.up, sizeof(Float3)) == 0 && a.verticalFovDeg == b.verticalFovDeg;
}

Session parseSession(const json& j, const std::filesystem::path& file) {
  if (!j.is_object()) throw KeyError{"(top level)", "expected a JSON object"};
  if (j.value("format", std::string()) != "tissue-session")
    throw KeyError{"format", "expected \"tissue-session\"; is this a session file?"};
  if (!j.contains("version") || !j["version"].is_number_integer() ||
      j["version"].get<int>() != kSessionVersion)
    throw KeyError{"version", "expected " + std::to_string(kSessionVersion)};
  for (const auto& [name, value] : j.items())
    if (name != "format" && name != "version" && name != "scenario" && name != "frame_time_s" &&
        name != "mesh_vertices" && name != "mesh_rest_sha256" && name != "frames" && name != "description")
      throw KeyError{name, "unknown key"};
  Session s;
  s.file = file;
  if (!j.contains("scenario") || !j["scenario"].is_string())
    throw KeyError{"scenario", "missing; give the scenario file's path, relative to the session"};
  const std::filesystem::path scenario = j["scenario"].get<std::string>();
  s.scenario = scenario.is_absolute() ? scenario : file.parent_path() / scenario;
  if (!j.contains("frame_time_s") || !j["frame_time_s"].is_number() ||
      !(j["frame_time_s"].get<double>() > 0.0))
    throw KeyError{"frame_time_s", "expected a positive number (s)"};
  s.frameTimeS = j["frame_time_s"].get<double>();
  if (!j.contains("mesh_vertices") || !j["mesh_vertices"].is_number_unsigned())
    throw KeyError{"mesh_vertices", "expected the simulated surface's vertex count"};
  s.meshVertices = j["mesh_vertices"].get<std::size_t>();
  s.meshRestSha256 = j.value("mesh_rest_sha256", std::string());
  if (!j.contains("frames") || !j["frames"].is_array() || j["frames"].empty())
    throw KeyError{"frames", "expected a non-empty list of frames"};
  // Bounded: each frame costs a few dozen bytes of the file, so the count is the file's to bear.
  s.frames.reserve(j["frames"].size());
  for (std::size_t i = 0; i < j["frames"].size(); ++i) {
    const json& f = j["frames"][i];
    const std::string key = "frames[" + std::to_string(i) + "]";
    if (!f.is_object()) throw KeyError{key, "expected {\"pose\": [x, y, z], \"grasp\": bool}"};
    SessionFrame frame;
    if (!f.contains("pose")) throw KeyError{key + ".pose", "missing; give [x, y, z] (mm)"};
    frame.toolPositionMm = vec3d(f["pose"], key + ".pose");
    if (f.contains("grasp")) {
      if (!f["grasp"].is_boolean()) throw KeyError{key + ".grasp", "expected true or false"};
      frame.grasp = f["grasp"].get<bool>();
    }
    if (f.contains("camera")) frame.camera = parseCamera(f["camera"], key + ".camera");
    if (f.contains("method")) {
      if (!f["method"].is_string()) throw KeyError{key + ".method", "expected a method name"};
      frame.method = f["method"].get<std::string>();
    }
    for (const auto& [name, value] : f.items())
      if (name != "pose" && name != "grasp" && name != "camera" && name != "method")
        throw KeyError{key + "." + name, "unknown key; use pose, grasp, camera, method"};
    s.frames.push_back(std::move(frame));
  }
  return s;
}

}  // namespace

Result<Session> loadSession(const std::filesystem::path& file) {
  auto text = readTextFile(file);
  if (!text) return text.error();
  try {
    return parseSession(json::parse(*text), file);
  } catch (const KeyError& e) {
    return Error{file.string() + ": " + e.key + ": " + e.what};
  } catch (const json::exception& e) {
    return Error{file.string() + ": not valid JSON (" + std::string(e.what()) +
                 "); fix the file or record it again"};
  }
}

Result<void> saveSession(const Session& session, const std::filesystem::path& file) {
  try {
    json frames = json::array();
    for (const SessionFrame& f : session.frames) {
      json j = {{"pose", toJson(f.toolPositionMm)}, {"grasp", f.grasp}};
      if (f.camera) j["camera"] = cameraJson(*f.camera);
      if (f.method) j["method"] = *f.method;
      frames.push_back(std::move(j));
    }
    const auto folder = std::filesystem::absolute(file).parent_path();
    const auto scenario = std::filesystem::absolute(session.scenario).lexically_relative(folder);
    const json j = {{"format", "tissue-session"},
                    {"version", kSessionVersion},
                    {"scenario", scenario.generic_string()},
                    {"frame_time_s", session.frameTimeS},
                    {"mesh_vertices", session.meshVertices},
                    {"mesh_rest_sha256", session.meshRestSha256},
                    {"frames", frames}};
    // One frame per line: diffable, and small enough to ship in data/sessions/.
    std::string text = "{\n";
    bool first = true;
    for (const auto& [key, value] : j.items()) {
      if (key == "frames") continue;
      text += std::string(first ? "" : ",\n") + "  " + json(key).dump() + ": " + value.dump();
      first = false;
    }
    text += ",\n  \"frames\": [\n";
    for (std::size_t i = 0; i < frames.size(); ++i)
      text += "    " + frames[i].dump() + (i + 1 < frames.size() ? ",\n" : "\n");
    text += "  ]\n}\n";
    return writeTextFileAtomic(file, text);
  } catch (const std::exception& e) {
    return Error{file.string() + ": cannot write the session (" + e.what() + ")"};
  }
}

InstrumentInput sessionInput(const Session& session, std::size_t index) {
  InstrumentInput in;
  if (index >= session.frames.size()) return in;
  const SessionFrame& f = session.frames[index];
  in.pose = sim::ToolPose{.position = f.toolPositionMm};
  in.grasp = f.grasp;
  return in;
}

Result<void> checkSessionMatches(const Session& session, const OrganLoop& loop) {
  const auto rest = loop.surface().geometricRestPositions();
  if (session.meshVertices != rest.size())
    return Error{session.file.string() + ": recorded on a mesh of " + std::to_string(session.meshVertices) +
                 " vertices, but " + loop.run().scenario().mesh.string() + " has " +
                 std::to_string(rest.size()) + "; replay it with the scenario it was recorded with"};
  if (!session.meshRestSha256.empty() && session.meshRestSha256 != positionsSha256(rest))
    return Error{session.file.string() + ": recorded on another mesh (mesh_rest_sha256 differs from " +
                 loop.run().scenario().mesh.string() + "); replay it with the scenario it was recorded with"};
  const double dt = loop.run().scenario().frameTime;
  if (std::abs(dt - session.frameTimeS) > 1e-12 * std::max(1.0, dt))
    return Error{session.file.string() + ": frame_time_s " + std::to_string(session.frameTimeS) +
                 " s differs from the scenario's dt " + std::to_string(dt) + " s; record it again"};
  return {};
}

std::string positionsSha256(std::span<const Float3> positions) {
  // Hash the floats' bytes in a fixed (little-endian) order so equal positions hash equally on
  // every machine.
  std::vector<unsigned char> bytes;
  bytes.reserve(positions.size() * 12);
  for (const Float3& p : positions)
    for (float c : {p.x, p.y, p.z}) {
      std::uint32_t u = 0;
      std::memcpy(&u, &c, 4);
      for (int b = 0; b < 4; ++b)
        bytes.push_back(static_cast<unsigned char>(u >> (8 * b)));
    }
  unsigned char digest[EVP_MAX_MD_SIZE];
  unsigned int length = 0;
  if (EVP_Digest(bytes.data(), bytes.size(), digest, &length, EVP_sha256(), nullptr) != 1) return {};
  static constexpr char kHex[] = "0123456789abcdef";
  std::string hex;
  for (unsigned int i = 0; i < length; ++i)
    hex += {kHex[digest[i] >> 4], kHex[digest[i] & 15]};
  return hex;
}

SessionRecorder::SessionRecorder(const OrganLoop& loop) {
  m_session.scenario = loop.run().scenario().file;
  m_session.frameTimeS = loop.run().scenario().frameTime;
  const auto rest = loop.surface().geometricRestPositions();
  m_session.meshVertices = rest.size();
  m_session.meshRestSha256 = positionsSha256(rest);
}

void SessionRecorder::recordFrame(const OrganLoop& loop, const render::Camera* camera,
                                  const std::string* method) {
  SessionFrame f;
  if (const sim::Instrument* tool = loop.run().instrument()) {
    f.toolPositionMm = tool->pose().position;
    f.grasp = tool->grasping();
  }
  if (camera && (!m_lastCamera || !sameCamera(*camera, *m_lastCamera))) f.camera = m_lastCamera = *camera;
  if (method && (!m_lastMethod || *method != *m_lastMethod)) f.method = m_lastMethod = *method;
  m_session.frames.push_back(std::move(f));
}

}  // namespace tissue::scene
