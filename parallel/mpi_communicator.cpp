#include "mpi_communicator.hpp"

#include <algorithm>
#include <climits>
#include <stdexcept>

namespace granshock {

namespace {

void require(int status, const char* what) {
  if (status != MPI_SUCCESS) throw std::runtime_error(std::string(what) + " failed");
}

}  // namespace

MpiCommunicator::MpiCommunicator(MPI_Comm comm) : comm_(comm) {
  require(MPI_Comm_rank(comm_, &rank_), "MPI_Comm_rank");
  require(MPI_Comm_size(comm_, &size_), "MPI_Comm_size");
}

double MpiCommunicator::max(double local) const {
  double out = 0;
  require(MPI_Allreduce(&local, &out, 1, MPI_DOUBLE, MPI_MAX, comm_), "MPI_Allreduce (max)");
  return out;
}

double MpiCommunicator::sum(double local) const {
  double out = 0;
  require(MPI_Allreduce(&local, &out, 1, MPI_DOUBLE, MPI_SUM, comm_), "MPI_Allreduce (sum)");
  return out;
}

long MpiCommunicator::sum(long local) const {
  long out = 0;
  require(MPI_Allreduce(&local, &out, 1, MPI_LONG, MPI_SUM, comm_), "MPI_Allreduce (sum)");
  return out;
}

bool MpiCommunicator::any(bool local) const {
  int flag = local ? 1 : 0, out = 0;
  require(MPI_Allreduce(&flag, &out, 1, MPI_INT, MPI_LOR, comm_), "MPI_Allreduce (any)");
  return out != 0;
}

void MpiCommunicator::sum_in_place(std::vector<double>& values) const {
  // In pieces of at most INT_MAX elements: MPI counts are int.
  for (std::size_t done = 0; done < values.size();) {
    const int count = int(std::min<std::size_t>(values.size() - done, INT_MAX));
    require(MPI_Allreduce(MPI_IN_PLACE, values.data() + done, count, MPI_DOUBLE, MPI_SUM, comm_),
            "MPI_Allreduce (sum in place)");
    done += std::size_t(count);
  }
}

}  // namespace granshock
