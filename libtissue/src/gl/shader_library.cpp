// Shader sources: embedded table, override folder, #define injection and #include resolution.
#include "tissue/gl/shader_library.h"

#include <cstdlib>
#include <fstream>
#include <sstream>

namespace tissue::gl {
namespace {

constexpr int kMaxIncludeDepth = 16;

bool startsWith(std::string_view s, std::string_view prefix) {
  return s.substr(0, prefix.size()) == prefix;
}

std::string_view trimLeft(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t'))
    s.remove_prefix(1);
  return s;
}

// Parses `#include "path"`; returns the path or empty when the line is not an include.
std::string includeTarget(std::string_view line) {
  line = trimLeft(line);
  if (!startsWith(line, "#")) return {};
  line = trimLeft(line.substr(1));
  if (!startsWith(line, "include")) return {};
  line = trimLeft(line.substr(7));
  if (line.size() < 2 || line.front() != '"') return {};
  const auto close = line.find('"', 1);
  if (close == std::string_view::npos) return {};
  return std::string(line.substr(1, close - 1));
}

struct Assembler {
  const ShaderLibrary& library;
  PreprocessedShader out;

  // Appends `name`'s lines to out.source, resolving includes; `defines` go after #version
  // of the top-level file (depth 0). Every file gets its own GLSL source-string number.
  Result<void> append(const std::string& name, std::span<const ShaderDefine> defines, int depth,
                      std::vector<std::string>& stack) {
    if (depth > kMaxIncludeDepth) return Error{"shader " + name + ": includes nested deeper than 16"};
    for (const auto& open : stack) {
      if (open == name) return Error{"shader " + name + ": include cycle (" + stack.front() + " ...)"};
    }
    auto text = library.source(name);
    if (!text) return text.error();
    stack.push_back(name);
    const int fileIndex = static_cast<int>(out.files.size());
    out.files.push_back(name);
    std::istringstream in(*text);
    std::string line;
    int lineNo = 0;
    bool sawVersion = depth > 0;
    while (std::getline(in, line)) {
      ++lineNo;
      if (const std::string target = includeTarget(line); !target.empty()) {
        // A file is pasted once per shader (include guards for free).
        bool already = false;
        for (const auto& f : out.files)
          already = already || f == target;
        if (!already) {
          auto r = append(target, {}, depth + 1, stack);
          if (!r)
            return Error{r.error().message + " (included from " + name + ":" + std::to_string(lineNo) + ")"};
        }
        out.source += "#line " + std::to_string(lineNo + 1) + " " + std::to_string(fileIndex) + "\n";
        continue;
      }
      out.source += line + "\n";
      if (!sawVersion && startsWith(trimLeft(line), "#version")) {
        sawVersion = true;
        for (const auto& d : defines)
          out.source += "#define " + d.name + " " + d.value + "\n";
        out.source += "#line " + std::to_string(lineNo + 1) + " " + std::to_string(fileIndex) + "\n";
      }
    }
    if (!sawVersion)
      return Error{"shader " + name + ": no #version line (tissue shaders start with #version 330 core)"};
    stack.pop_back();
    return {};
  }
};

}  // namespace

ShaderLibrary::ShaderLibrary(ShaderLibrarySettings settings)
    : m_overrideDir(std::move(settings.overrideDir)) {}

Result<std::string> ShaderLibrary::source(std::string_view name) const {
  // Step 1: the override folder (live editing) wins when it holds the file.
  if (!m_overrideDir.empty()) {
    const auto path = m_overrideDir / std::filesystem::path(name);
    if (std::filesystem::is_regular_file(path)) {
      std::ifstream file(path, std::ios::binary);
      if (!file) return Error{"shader " + path.string() + ": cannot be read"};
      std::ostringstream text;
      text << file.rdbuf();
      return text.str();
    }
  }
  // Step 2: the copy embedded at build time.
  for (const auto& shader : detail::embeddedShaders()) {
    if (name == shader.name) return std::string(shader.source);
  }
  std::string where = m_overrideDir.empty() ? "" : " nor in " + m_overrideDir.string();
  return Error{"shader " + std::string(name) + ": not embedded" + where +
               "; add it under shaders/ and rebuild, or set TISSUE_SHADER_DIR"};
}

Result<PreprocessedShader> ShaderLibrary::preprocess(std::string_view name,
                                                     std::span<const ShaderDefine> defines) const {
  Assembler assembler{*this, {}};
  std::vector<std::string> stack;
  auto r = assembler.append(std::string(name), defines, 0, stack);
  if (!r) return r.error();
  return std::move(assembler.out);
}

}  // namespace tissue::gl
