// The stand-in poke: push within a radius while held, exponential return to rest.
#include "instrument_poke.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "vec3_ops.h"

namespace tissue::viewer {
namespace {

/// Displacements shorter than this (mm) snap to zero, so relaxation ends in finite time.
constexpr float kRestToleranceMm = 1e-4f;

}  // namespace

InstrumentPoke::InstrumentPoke(std::span<const Float3> restPositions, const PokeSettings& settings)
    : m_settings(settings),
      m_rest(restPositions.begin(), restPositions.end()),
      m_displacement(restPositions.size()),
      m_positions(m_rest) {}

void InstrumentPoke::press(Float3 contactMm, Float3 direction, std::span<const Float3> currentPositions) {
  Contact contact;
  contact.direction = normalize(direction);
  const float radius = m_settings.radiusMm;
  for (std::uint32_t i = 0; i < currentPositions.size(); ++i) {
    const float r = length(currentPositions[i] - contactMm);
    if (r >= radius) continue;
    // Cosine falloff: 1 at the contact, 0 (with zero slope) at the radius.
    contact.vertices.push_back(i);
    contact.weights.push_back(0.5f * (1.0f + std::cos(std::numbers::pi_v<float> * r / radius)));
  }
  m_contact = std::move(contact);
}

void InstrumentPoke::release() {
  m_contact.reset();
}

void InstrumentPoke::reset() {
  m_contact.reset();
  std::fill(m_displacement.begin(), m_displacement.end(), Float3{});
  m_positions = m_rest;
  m_atRest = true;
}

bool InstrumentPoke::step(float dtS) {
  if (m_atRest && !m_contact) return false;
  // Relax: d(t + dt) = d(t) exp(-dt / tau), tau chosen so that 1 % remains after relaxTimeS.
  const float tau = m_settings.relaxTimeS / std::log(100.0f);
  const float decay = std::exp(-std::max(dtS, 0.0f) / tau);
  bool anyDisplaced = false;
  for (Float3& d : m_displacement) {
    d = d * decay;
    if (length(d) < kRestToleranceMm) d = {};
    anyDisplaced = anyDisplaced || d != Float3{};
  }
  // Push: the held instrument deepens towards the full depth and holds its vertices there.
  if (m_contact) {
    Contact& c = *m_contact;
    c.depthMm = std::min(c.depthMm + m_settings.pushSpeedMmPerS * std::max(dtS, 0.0f), m_settings.maxDepthMm);
    for (std::size_t k = 0; k < c.vertices.size(); ++k)
      m_displacement[c.vertices[k]] = c.direction * (c.depthMm * c.weights[k]);
    anyDisplaced = anyDisplaced || (c.depthMm > 0.0f && !c.vertices.empty());
  }
  for (std::size_t i = 0; i < m_rest.size(); ++i)
    m_positions[i] = m_rest[i] + m_displacement[i];
  m_atRest = !anyDisplaced;
  return true;
}

}  // namespace tissue::viewer
