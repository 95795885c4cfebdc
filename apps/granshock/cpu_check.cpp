#include "apps/granshock/cpu_check.hpp"

#include <unistd.h>

#include "cases/build_info/build_description.hpp"

namespace granshock {

std::vector<std::string> missing_cpu_features(
    const char* const* compiled, const std::function<bool(const std::string&)>& supported) {
  std::vector<std::string> missing;
  for (const char* const* name = compiled; *name != nullptr; ++name)
    if (!supported(*name)) missing.emplace_back(*name);
  return missing;
}

// Plain strings: this runs before the program's libraries have initialised (main.cpp).
std::string cpu_refusal(const std::vector<std::string>& missing, const std::string& march) {
  std::string names;
  for (const std::string& name : missing) names += (names.empty() ? "" : ", ") + name;
  return "this granshock was compiled for another CPU (-march " + march + ") and uses " + names +
         ", which this CPU lacks; build it on this machine, or for any CPU with cmake "
         "-DGRANSHOCK_NATIVE=OFF (docs/study.md, \"On a cluster\")";
}

namespace {

// __builtin_cpu_supports takes a literal name.
bool cpu_supports(const std::string& name) {
#if (defined(__x86_64__) || defined(__i386__)) && (defined(__GNUC__) || defined(__clang__))
  __builtin_cpu_init();
  if (name == "sse4.2") return __builtin_cpu_supports("sse4.2");
  if (name == "avx") return __builtin_cpu_supports("avx");
  if (name == "avx2") return __builtin_cpu_supports("avx2");
  if (name == "fma") return __builtin_cpu_supports("fma");
  if (name == "bmi2") return __builtin_cpu_supports("bmi2");
  if (name == "avx512f") return __builtin_cpu_supports("avx512f");
  if (name == "avx512cd") return __builtin_cpu_supports("avx512cd");
  if (name == "avx512dq") return __builtin_cpu_supports("avx512dq");
  if (name == "avx512bw") return __builtin_cpu_supports("avx512bw");
  if (name == "avx512vl") return __builtin_cpu_supports("avx512vl");
#endif
  (void)name;
  return true;  // a name this check cannot ask about: leave it to the CPU
}

}  // namespace

std::string check_this_cpu() {
  const std::vector<std::string> missing = missing_cpu_features(kCompiledCpuFeatures, cpu_supports);
  return missing.empty() ? std::string() : cpu_refusal(missing, build_march());
}

}  // namespace granshock

namespace granshock {

void exit_unless_this_cpu_runs_the_build() {
  const std::string refusal = check_this_cpu();
  if (refusal.empty()) return;
  const std::string line = "granshock: error: " + refusal + "\n";
  [[maybe_unused]] const ssize_t written = ::write(2, line.data(), line.size());
  ::_exit(2);
}

}  // namespace granshock
