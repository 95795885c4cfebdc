#include "apps/granshock/build_info.hpp"

#include <Kokkos_Core.hpp>
#include <nlohmann/json.hpp>

#include "cases/build_info/build_description.hpp"
#include "core/choice_names.hpp"
#include "kernels/device/backends.hpp"
#include "models/law_parameters.hpp"
#include "models/obstacle_shapes.hpp"
#include "parallel/mpi_runtime.hpp"

namespace granshock {

std::string build_info_json(int processes) {
  nlohmann::json j = build_description();
  // The key `info` has always had for the version.
  j["granshock"] = j["version"];
  j["threads"] = Kokkos::DefaultHostExecutionSpace().concurrency();
  // Which branches the kernels take (docs/cuda.md, "Branch points"), and whether Kokkos
  // checks every View index (cmake/install_kokkos_debug.sh).
  j["kernel_paths"] = uses_host_paths<Kokkos::DefaultExecutionSpace>() ? "host" : "device";
#ifdef KOKKOS_ENABLE_DEBUG_BOUNDS_CHECK
  j["bounds_check"] = true;
#else
  j["bounds_check"] = false;
#endif
  // MPI: linked always (parallel HDF5); started only under a launcher (docs/parallel.md).
  j["mpi"] = {{"library", MpiRuntime::library_version()},
              {"launched", MpiRuntime::launched_by_mpi()},
              {"processes", processes}};
  // The names every choice takes (core/choice_names.hpp), among them the contact laws this
  // build compiles (each has a law in kernels/models/models.hpp).
  nlohmann::json choices;
  for_each_choice([&](auto value) {
    using Enum = decltype(value);
    choices[Choices<Enum>::what] = choice_names<Enum>();
  });
  j["choices"] = choices;
  // The keys each contact law and obstacle shape takes (models/law_parameters.hpp,
  // obstacle_shapes.hpp): name, type, meaning, range and default, as a scene gives them.
  nlohmann::json laws;
  for (const auto& c : Choices<ContactModelKind>::table) {
    nlohmann::json keys = nlohmann::json::array();
    with_law_parameters(c.value, [&](auto parameters) {
      for (const LawKey& k : parameters.keys)
        keys.push_back({{"key", std::string("contact.") + k.name},
                        {"type", k.type},
                        {"meaning", k.meaning},
                        {"accepted", {k.lo, k.hi}},
                        {"default", k.fallback == LawKey::Default::required ? "required"
                                                                            : "inflow.velocity"}});
    });
    laws[c.name] = keys;
  }
  j["contact_law_keys"] = laws;
  nlohmann::json shapes;
  for_each_obstacle_shape([&](auto shape) {
    nlohmann::json keys = nlohmann::json::array();
    for (const ShapeKey& k : shape.keys) {
      nlohmann::json key = {
          {"key", std::string("obstacle.") + k.name}, {"type", k.type()}, {"meaning", k.meaning}};
      if (k.kind == ShapeKey::Kind::angle) key["accepted"] = {k.lo, k.hi};
      key["default"] = k.required() ? nlohmann::json("required") : nlohmann::json(k.fallback);
      keys.push_back(key);
    }
    shapes[shape.name] = keys;
  });
  j["obstacle_shape_keys"] = shapes;
  return j.dump(2);
}

}  // namespace granshock
