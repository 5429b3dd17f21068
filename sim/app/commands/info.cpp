// tissue-sim info: which GL context tissue gets here and what the driver says about itself.
#include "command.h"
#include "gl_environment.h"
#include "output.h"
#include "tissue/context/headless_context.h"

namespace tissue::sim_app {

void registerInfoCommand(CLI::App& app, const GlobalOptions& global, int& exitCode) {
  auto* cmd = app.add_subcommand("info",
                                 "describe the headless GL context (TISSUE_GL_CONTEXT=egl|osmesa, "
                                 "TISSUE_EGL_PLATFORM=device|surfaceless)");
  cmd->callback([&global, &exitCode] {
    auto context = createAppContext({}, false);
    if (!context) {
      exitCode = fail("info", context.error().message);
      return;
    }
    const context::ContextInfo& info = (*context)->info();
    nlohmann::json out;
    out["gl_context"] = info.backend;
    out["gl_platform"] = info.platform;
    out["gl_vendor"] = info.vendor;
    out["gl_renderer"] = info.renderer;
    out["gl_version"] = info.version;
    printResult(global, out);
  });
}

}  // namespace tissue::sim_app
