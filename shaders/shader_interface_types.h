// The C++ types of the shader interface's entries; the entries themselves
// are generated from shaders/shader_interface.def into
// shaders/shader_interface.h (shaders/shader_interface.cmake).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

namespace shaders {

// Deliberately wrong variants of the model (SPEC 7, mutation check), selected
// by the specialization constant MUTANT. 0, None, is the model itself; no
// other value is ever a default.
enum class Mutant : int;

// Where a mutant is wrong: in the GLSL (a MUTANT_<NAME> constant), in the
// data the CPU hands the backend (conformance/cpu_mutants.h), or in the
// backends' pipeline state (volumeRule, shadowLookupCompare).
enum class MutantKind { Shader, Cpu, Pipeline };

struct MutantName {
  Mutant mutant;
  std::string_view name;  // the --mutant spelling
  MutantKind kind;
  std::string_view what;  // one line for listings and reports
};

// Deliberately different but legal implementations (SPEC 7, admissible
// variants), selected by the specialization constant ADMISSIBLE. 0, None, is
// the model itself.
enum class Admissible : int;

// Where a variant is realised: on every backend, on Vulkan only (OpenGL's
// GLSL 330 cannot express it), or nowhere (a freedom listed for
// completeness that no shader can realise on these drivers).
enum class AdmissibleApis { All, Vulkan, None };

struct AdmissibleName {
  Admissible variant;
  std::string_view name;  // the --admissible spelling
  AdmissibleApis apis;
  std::string_view what;   // what it does, one line
  std::string_view grant;  // the specification's sentence that allows it
};

namespace binding {

// A uniform block: Vulkan's set and binding, and the OpenGL binding point the
// backend binds it to by name (GLSL 330 has no binding qualifiers).
struct UniformBlock {
  const char* name;
  std::uint32_t set;
  std::uint32_t binding;
  std::uint32_t glBinding;
};

// One sampler, or several (slots) at consecutive bindings and texture units.
struct Texture {
  std::span<const char* const> names;  // the GLSL sampler of each
  std::uint32_t set;
  std::uint32_t firstBinding;
  std::int32_t firstGlUnit;

  constexpr std::size_t count() const { return names.size(); }
  constexpr const char* name(std::size_t i = 0) const { return names[i]; }
  constexpr std::uint32_t binding(std::size_t i = 0) const { return firstBinding + std::uint32_t(i); }
  constexpr std::int32_t glUnit(std::size_t i = 0) const { return firstGlUnit + std::int32_t(i); }
};

}  // namespace binding
}  // namespace shaders
