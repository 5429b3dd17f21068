#pragma once
/// \file
/// Recorded sessions: what a trainee did, frame by frame (instrument pose, grasp and release,
/// camera, shading-method switches), written by the viewer or by `tissue-sim simulate --record`
/// and re-run headless and deterministically by `tissue-sim replay` (the deformation-plus-render
/// performance test). The file format is JSON (docs/SESSIONS.md):
///
///   {"format": "tissue-session", "version": 1, "scenario": "path (relative to the session)",
///    "frame_time_s": 0.0166, "mesh_vertices": 13826, "mesh_rest_sha256": "...",
///    "frames": [{"pose": [x, y, z] (mm), "grasp": true|false, "camera": {...}?, "method": "..."?}, ...]}

#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "tissue/core/result.h"
#include "tissue/core/types.h"
#include "tissue/render/scene.h"
#include "tissue/scene/organ_loop.h"
#include "tissue/sim/vec3.h"

namespace tissue::scene {

/// One recorded frame: the input the loop got before simulating it.
struct SessionFrame {
  sim::Vec3d toolPositionMm{};  ///< mm, the tool's position at the end of the frame (double: replays exactly)
  bool grasp = false;           ///< grasping during the frame
  std::optional<render::Camera> camera;  ///< when the camera changed at this frame
  std::optional<std::string> method;     ///< when the shading method changed ("lit", ...)
};

/// A recorded session.
struct Session {
  std::filesystem::path file;      ///< where it was read from (messages, relative paths)
  std::filesystem::path scenario;  ///< the scenario it was recorded with (resolved path)
  double frameTimeS = 1.0 / 60.0;  ///< s per frame
  std::size_t meshVertices = 0;    ///< geometric vertices of the simulated surface
  std::string meshRestSha256;      ///< SHA-256 of the rest positions (positionsSha256)
  std::vector<SessionFrame> frames;
};

/// Reads a session file. Errors name the file, the frame and the key, and say how to fix it
/// (e.g. "s.json: frames[12].pose: expected 3 finite numbers (mm)").
Result<Session> loadSession(const std::filesystem::path& file);
/// Writes `session` atomically; the scenario path is stored relative to the session's folder.
Result<void> saveSession(const Session& session, const std::filesystem::path& file);

/// The loop input of frame `index` of `session` (pose and grasp).
InstrumentInput sessionInput(const Session& session, std::size_t index);

/// Fails, with one line that says how to fix it, when `session` was recorded on another mesh
/// than the one `loop` simulates (vertex count or rest positions differ) or with another frame time.
Result<void> checkSessionMatches(const Session& session, const OrganLoop& loop);

/// SHA-256 (hex) of positions as little-endian IEEE floats, x y z per vertex: the fingerprint
/// two runs compare (bit-identical positions give equal hashes).
std::string positionsSha256(std::span<const Float3> positions);

/// Records a session frame by frame (the viewer, `simulate --record`).
class SessionRecorder {
 public:
  /// Starts a session of `loop`'s scenario and mesh.
  explicit SessionRecorder(const OrganLoop& loop);
  /// Appends the frame the loop just ran: the tool's pose and grasp state after it, and the
  /// camera and method when they differ from the last recorded ones.
  void recordFrame(const OrganLoop& loop, const render::Camera* camera = nullptr,
                   const std::string* method = nullptr);
  const Session& session() const { return m_session; }

 private:
  Session m_session;
  std::optional<render::Camera> m_lastCamera;
  std::optional<std::string> m_lastMethod;
};

}  // namespace tissue::scene
