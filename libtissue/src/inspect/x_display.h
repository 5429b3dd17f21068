#pragma once
/// \file
/// An X display for VTK's rendering (Debian's VTK is built for X only). Opens $DISPLAY when it
/// works; otherwise starts a private Xvfb (lets it pick a free display number with -displayfd)
/// and stops it at destruction. Nothing global is changed: the Display* is handed to VTK.

#include <sys/types.h>

#include "tissue/core/result.h"

struct _XDisplay;

namespace tissue::inspect {

/// An open X connection, and the Xvfb behind it when we started one. Move-only.
class XDisplay {
 public:
  /// $DISPLAY if it can be opened, else a fresh Xvfb (fails when Xvfb is missing or dies).
  static Result<XDisplay> open();

  XDisplay(XDisplay&& other) noexcept;
  XDisplay& operator=(XDisplay&& other) noexcept;
  XDisplay(const XDisplay&) = delete;
  XDisplay& operator=(const XDisplay&) = delete;
  ~XDisplay();

  /// The Xlib Display* as the void* VTK's SetDisplayId takes.
  void* displayId() const { return m_display; }

 private:
  XDisplay(_XDisplay* display, pid_t server) : m_display(display), m_server(server) {}
  void close();

  _XDisplay* m_display = nullptr;
  pid_t m_server = -1;  ///< the Xvfb we started, or -1
};

}  // namespace tissue::inspect
