#pragma once
/// \file
/// What every fuzz target shares: the input written to a file with the loader's extension (the
/// loaders read paths, as tissue-sim and hosts call them), and the check that a refusal is one
/// line naming the file (issue 14: "one line naming the file, the place and the fix").

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace tissue::fuzz {

/// The input as the file "<tmp>/tissue_fuzz_<pid>/input<extension>", rewritten per input (one
/// file per process, so parallel jobs never share one).
inline std::filesystem::path inputFile(const std::uint8_t* data, std::size_t size, const char* extension) {
  const auto dir = std::filesystem::temp_directory_path() / ("tissue_fuzz_" + std::to_string(::getpid()));
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  const auto path = dir / (std::string("input") + extension);
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  return path;
}

/// A refusal must be one non-empty line that names `file` (its file name suffices); anything
/// else is a finding, reported and trapped so that libFuzzer keeps the input.
inline void checkRefusal(const std::string& message, const std::filesystem::path& file) {
  const std::string name = file.filename().string();
  const bool oneLine = !message.empty() && message.find('\n') == std::string::npos;
  const bool named = message.find(name) != std::string::npos;
  if (oneLine && named) return;
  std::fprintf(stderr, "fuzz: bad refusal (%s%s): %s\n", oneLine ? "" : "not one line; ",
               named ? "" : "does not name the file", message.c_str());
  __builtin_trap();
}

}  // namespace tissue::fuzz
