#include "parallel/mpi_runtime.hpp"

#include <mpi.h>

#include <cstdlib>
#include <stdexcept>

namespace granshock {

bool MpiRuntime::launched_by_mpi() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_SIZE"})
    if (const char* v = std::getenv(name); v != nullptr && *v != '\0') return true;
  return false;
}

std::string MpiRuntime::library_version() {
  char text[MPI_MAX_LIBRARY_VERSION_STRING];
  int length = 0;
  MPI_Get_library_version(text, &length);
  std::string out(text, std::size_t(length));
  while (!out.empty() && out.back() == '\0') out.pop_back();  // Open MPI counts its NUL
  // The first line names the library; the rest is build detail.
  if (const auto end = out.find_first_of("\r\n"); end != std::string::npos) out.resize(end);
  return out;
}

MpiRuntime::MpiRuntime(int& argc, char**& argv) {
  if (!launched_by_mpi()) return;
  int provided = 0;
  if (MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided) != MPI_SUCCESS)
    throw std::runtime_error("MPI_Init_thread failed");
  active_ = true;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

void MpiRuntime::abort(int code) const {
  if (active_) MPI_Abort(MPI_COMM_WORLD, code);
  std::exit(code);
}

MpiRuntime::~MpiRuntime() {
  if (active_) MPI_Finalize();
}

}  // namespace granshock
