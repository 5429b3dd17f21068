#pragma once
/// \file
/// A stand-in for the instrument-tissue contact until the mass-spring simulator (issue 3)
/// moves the mesh: while held, the instrument pushes the vertices near its contact point
/// along its direction, deepest at the contact and fading to zero at a radius with a cosine
/// falloff; once released, every displacement returns to rest exponentially. No dynamics, no
/// volume preservation, no collisions: the simulator replaces all of this.

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "tissue/core/types.h"

namespace tissue::viewer {

/// How the instrument pushes and how the tissue relaxes.
struct PokeSettings {
  float radiusMm = 15.0f;         ///< mm; vertices farther than this from the contact never move
  float maxDepthMm = 12.0f;       ///< mm; displacement of the contact point at full push
  float pushSpeedMmPerS = 60.0f;  ///< mm/s; how fast the push deepens while the button is held
  float relaxTimeS = 0.3f;        ///< s; after release, displacements fall below 1 % within this time
};

/// The poke's state over time: one displacement per geometric vertex on top of the rest shape.
class InstrumentPoke {
 public:
  /// `restPositions`: one position (mm) per geometric vertex, copied.
  explicit InstrumentPoke(std::span<const Float3> restPositions, const PokeSettings& settings = {});

  /// The instrument touches the tissue at `contactMm` (mm) and will push along `direction`
  /// (unit). `currentPositions` (mm, one per vertex) decide which vertices lie within the radius.
  void press(Float3 contactMm, Float3 direction, std::span<const Float3> currentPositions);
  /// The instrument lets go: the tissue starts relaxing.
  void release();
  /// Back to the rest shape at once, instrument released.
  void reset();

  /// Advances time by `dtS` seconds: the push deepens (held) and all other displacement
  /// relaxes. Returns whether any position changed.
  bool step(float dtS);

  /// Current positions (mm), rest + displacement, one per geometric vertex.
  std::span<const Float3> positions() const { return m_positions; }
  /// Current displacement of each vertex from rest (mm).
  std::span<const Float3> displacements() const { return m_displacement; }
  bool pressed() const { return m_contact.has_value(); }
  /// mm; how deep the held instrument pushes now (0 when released).
  float depthMm() const { return m_contact ? m_contact->depthMm : 0.0f; }
  const PokeSettings& settings() const { return m_settings; }

 private:
  /// The held instrument: its direction, push depth and the vertices it moves with weights.
  struct Contact {
    Float3 direction;
    float depthMm = 0.0f;
    std::vector<std::uint32_t> vertices;
    std::vector<float> weights;  ///< unitless 0..1, cosine falloff with distance
  };

  PokeSettings m_settings;
  std::vector<Float3> m_rest;
  std::vector<Float3> m_displacement;
  std::vector<Float3> m_positions;
  std::optional<Contact> m_contact;
  bool m_atRest = true;
};

}  // namespace tissue::viewer
