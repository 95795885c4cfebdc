// MPI for granshock's programs (docs/parallel.md). MPI starts only when an MPI launcher
// started the process (mpirun, srun, mpiexec: it leaves its rank in the environment), so
// that a plain `granshock run` neither needs nor touches MPI. Threads: MPI is called from
// the main thread only (MPI_THREAD_FUNNELED); OpenMP threads work between the calls.
#pragma once

#include <string>

namespace granshock {

class MpiRuntime {
 public:
  MpiRuntime(int& argc, char**& argv);
  ~MpiRuntime();
  MpiRuntime(const MpiRuntime&) = delete;
  MpiRuntime& operator=(const MpiRuntime&) = delete;

  bool active() const { return active_; }  // MPI was started (a launcher started us)
  int rank() const { return rank_; }
  int size() const { return size_; }
  // Ends every process of the job with `code` (a failure that the other ranks cannot know
  // of: they would wait for this one in their next collective operation).
  [[noreturn]] void abort(int code) const;

  // Whether a launcher started this process: Open MPI (OMPI_COMM_WORLD_SIZE), PMIx
  // (PMIX_RANK), MPICH/Hydra and Slurm's PMI (PMI_SIZE).
  static bool launched_by_mpi();
  // The MPI library's own name and version, e.g. "Open MPI v4.1.4, ...".
  static std::string library_version();

 private:
  bool active_ = false;
  int rank_ = 0;
  int size_ = 1;
};

}  // namespace granshock
