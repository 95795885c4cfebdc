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

std::vector<char> MpiCommunicator::send_receive(const std::vector<char>& bytes, int dest,
                                                int source) const {
  const int to = dest == kNone ? MPI_PROC_NULL : dest;
  const int from = source == kNone ? MPI_PROC_NULL : source;
  if (bytes.size() > std::size_t(INT_MAX))
    throw std::runtime_error("a halo message of more than 2 GiB");
  // The size first, then the bytes: the receiver allocates what it is sent.
  int count = int(bytes.size()), incoming = 0;
  require(MPI_Sendrecv(&count, 1, MPI_INT, to, 1, &incoming, 1, MPI_INT, from, 1, comm_,
                       MPI_STATUS_IGNORE),
          "MPI_Sendrecv (size)");
  std::vector<char> received(static_cast<std::size_t>(incoming));
  require(MPI_Sendrecv(bytes.data(), count, MPI_BYTE, to, 2, received.data(), incoming, MPI_BYTE,
                       from, 2, comm_, MPI_STATUS_IGNORE),
          "MPI_Sendrecv (bytes)");
  return received;
}

}  // namespace granshock
