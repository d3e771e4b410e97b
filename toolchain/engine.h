// The engines that run a program (`--engine`): one name each, in one table
// for the option's parser, its help and the code that picks the engine.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

namespace mbc::toolchain {

enum class Engine {
  Jit,    // native code of the JIT (or the compiled-code cache)
  Interp, // the reference interpreter over the AST
  Ir,     // the IR evaluator
};

inline constexpr std::array<std::pair<Engine, std::string_view>, 3>
    kEngineNames = {
        {{Engine::Jit, "jit"}, {Engine::Interp, "interp"}, {Engine::Ir, "ir"}}};

/// The engine of an `--engine` value; none for another word.
inline std::optional<Engine> engineNamed(std::string_view name) {
  for (const auto& [engine, engineName] : kEngineNames) {
    if (engineName == name) {
      return engine;
    }
  }
  return std::nullopt;
}

/// "jit|interp|ir" (sep "|") or "jit, interp or ir" (the last sep " or ").
inline std::string engineList(std::string_view sep, std::string_view last) {
  std::string out;
  for (std::size_t i = 0; i < kEngineNames.size(); ++i) {
    out += i == 0 ? "" : i + 1 == kEngineNames.size() ? last : sep;
    out += kEngineNames[i].second;
  }
  return out;
}

} // namespace mbc::toolchain
