#include "core/Migration.hpp"

#include <Teuchos_DefaultMpiComm.hpp>

#include <mpi.h>

namespace impm {

namespace {

MPI_Comm rawComm(const Comm& comm) {
  const auto* mpi = dynamic_cast<const Teuchos::MpiComm<int>*>(&comm);
  return mpi ? (*mpi->getRawMpiComm())() : MPI_COMM_SELF;
}

}  // namespace

template <int Dim>
std::size_t migrateParticles(ParticleSet<Dim>& particles, const std::vector<int>& destination,
                             const Comm& comm) {
  const int size = comm.getSize(), rank = comm.getRank();
  const std::size_t n = particles.size();
  int leaving = 0;
  for (int d : destination)
    leaving += d != rank;
  int anyLeaving = 0;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, leaving, Teuchos::outArg(anyLeaving));
  if (anyLeaving == 0)
    return 0;

  // Send order: grouped by destination rank; staying particles first in their old order.
  std::vector<int> sendCount(size, 0), recvCount(size, 0);
  std::vector<std::size_t> staying, sendOrder;
  for (std::size_t p = 0; p < n; ++p)
    if (destination[p] == rank)
      staying.push_back(p);
  for (int r = 0; r < size; ++r)
    for (std::size_t p = 0; p < n; ++p)
      if (destination[p] == r && r != rank)
        sendOrder.push_back(p), ++sendCount[r];
  MPI_Comm mpi = rawComm(comm);
  MPI_Alltoall(sendCount.data(), 1, MPI_INT, recvCount.data(), 1, MPI_INT, mpi);
  std::size_t arriving = 0;
  for (int c : recvCount)
    arriving += c;
  const std::size_t kept = staying.size(), total = kept + arriving;

  particles.forEachField([&](auto& view) {
    using View = std::decay_t<decltype(view)>;
    auto host = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), view);
    using Value = typename View::non_const_value_type;
    std::size_t width = 1;  // values per particle, from the static extents
    for (unsigned r = 1; r < View::rank; ++r)
      width *= view.extent(r);
    const std::size_t rowBytes = width * sizeof(Value);
    std::vector<char> send(sendOrder.size() * rowBytes), recv(arriving * rowBytes);
    const char* data = reinterpret_cast<const char*>(host.data());
    for (std::size_t k = 0; k < sendOrder.size(); ++k)
      std::copy(data + sendOrder[k] * rowBytes, data + (sendOrder[k] + 1) * rowBytes,
                send.begin() + k * rowBytes);
    std::vector<int> sendBytes(size), recvBytes(size), sendOffset(size, 0), recvOffset(size, 0);
    for (int r = 0; r < size; ++r) {
      sendBytes[r] = static_cast<int>(sendCount[r] * rowBytes);
      recvBytes[r] = static_cast<int>(recvCount[r] * rowBytes);
      if (r) {
        sendOffset[r] = sendOffset[r - 1] + sendBytes[r - 1];
        recvOffset[r] = recvOffset[r - 1] + recvBytes[r - 1];
      }
    }
    MPI_Alltoallv(send.data(), sendBytes.data(), sendOffset.data(), MPI_BYTE, recv.data(),
                  recvBytes.data(), recvOffset.data(), MPI_BYTE, mpi);
    View fresh(view.label(), total);
    auto freshHost = Kokkos::create_mirror_view(fresh);
    char* out = reinterpret_cast<char*>(freshHost.data());
    for (std::size_t k = 0; k < kept; ++k)
      std::copy(data + staying[k] * rowBytes, data + (staying[k] + 1) * rowBytes,
                out + k * rowBytes);
    std::copy(recv.begin(), recv.end(), out + kept * rowBytes);
    Kokkos::deep_copy(fresh, freshHost);
    view = fresh;
  });
  return sendOrder.size();
}

template <int Dim>
std::size_t migrateToOwners(ParticleSet<Dim>& particles, const Decomposition<Dim>& decomposition,
                            const Comm& comm) {
  auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), particles.x);
  std::vector<int> destination(particles.size());
  for (std::size_t p = 0; p < particles.size(); ++p) {
    double at[Dim];
    for (int d = 0; d < Dim; ++d)
      at[d] = x(p, d);
    destination[p] = decomposition.ownerOfPoint(at);
  }
  return migrateParticles(particles, destination, comm);
}

template std::size_t migrateParticles<1>(ParticleSet<1>&, const std::vector<int>&, const Comm&);
template std::size_t migrateParticles<2>(ParticleSet<2>&, const std::vector<int>&, const Comm&);
template std::size_t migrateToOwners<1>(ParticleSet<1>&, const Decomposition<1>&, const Comm&);
template std::size_t migrateToOwners<2>(ParticleSet<2>&, const Decomposition<2>&, const Comm&);

}  // namespace impm
