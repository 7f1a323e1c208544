#include "core/Migration.hpp"

#include <algorithm>

#include <Teuchos_CommHelpers.hpp>

#include "core/MpiComm.hpp"

namespace impm {

namespace {

// Sends row sendOrder[k] of `host` (rowBytes each) to the rank it is grouped under
// (sendCount per rank, in rank order); returns the rows received, in rank order.
template <class Host>
std::vector<char> exchangeRows(const Host& host, std::size_t rowBytes,
                               const std::vector<std::size_t>& sendOrder,
                               const std::vector<int>& sendCount, const std::vector<int>& recvCount,
                               MPI_Comm mpi) {
  const int size = static_cast<int>(sendCount.size());
  std::size_t arriving = 0;
  for (int c : recvCount)
    arriving += c;
  std::vector<char> send(sendOrder.size() * rowBytes), recv(arriving * rowBytes);
  const char* data = reinterpret_cast<const char*>(host.data());
  for (std::size_t k = 0; k < sendOrder.size(); ++k)
    std::copy(data + sendOrder[k] * rowBytes, data + (sendOrder[k] + 1) * rowBytes,
              send.begin() + k * rowBytes);
  std::vector<int> sendBytes(size), recvBytes(size), sendOffset(size, 0), recvOffset(size, 0);
  for (int r = 0; r < size; ++r) {
    sendBytes[r] = static_cast<int>(sendCount[r] * rowBytes);
    recvBytes[r] = static_cast<int>(recvCount[r] * rowBytes);
  }
  // The offsets in a loop of their own: computed in the loop above, GCC 12.2 at -O3 left the
  // receive offsets at zero (seen on 3 ranks, where they are not all zero).
  for (int r = 1; r < size; ++r) {
    sendOffset[r] = sendOffset[r - 1] + sendBytes[r - 1];
    recvOffset[r] = recvOffset[r - 1] + recvBytes[r - 1];
  }
  MPI_Alltoallv(send.data(), sendBytes.data(), sendOffset.data(), MPI_BYTE, recv.data(),
                recvBytes.data(), recvOffset.data(), MPI_BYTE, mpi);
  return recv;
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

  // Send order: grouped by destination rank, in the old order within each group.
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
  const std::size_t kept = staying.size();

  // The new order: by id, so that the order of the particles on a rank (and with it every
  // sum over them) depends only on which particles it holds, not on how they came (a
  // restarted run sums in the same order as the uninterrupted one).  Staying particles are
  // already sorted; arrivals are sorted and merged in.
  auto ids = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), particles.id);
  const auto idBytes = exchangeRows(ids, sizeof(GlobalId), sendOrder, sendCount, recvCount, mpi);
  const std::size_t total = kept + idBytes.size() / sizeof(GlobalId);
  std::vector<GlobalId> newIds(total);
  for (std::size_t k = 0; k < kept; ++k)
    newIds[k] = ids(staying[k]);
  std::copy(idBytes.begin(), idBytes.end(), reinterpret_cast<char*>(newIds.data() + kept));
  std::vector<std::size_t> order(total);  // order[k]: the k-th new particle among kept + arrivals
  for (std::size_t k = 0; k < total; ++k)
    order[k] = k;
  const auto byId = [&](std::size_t a, std::size_t b) { return newIds[a] < newIds[b]; };
  if (!std::is_sorted(order.begin(), order.begin() + kept, byId))
    std::sort(order.begin(), order.begin() + kept, byId);
  std::sort(order.begin() + kept, order.end(), byId);
  std::inplace_merge(order.begin(), order.begin() + kept, order.end(), byId);

  particles.forEachField([&](const FieldSpec& spec, auto& view) {
    using View = std::decay_t<decltype(view)>;
    if (!spec.migrate) {  // recomputed before it is next read
      view = allocateField(spec.name, view, total);
      return;
    }
    auto host = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), view);
    const std::size_t rowBytes = fieldWidth(view) * sizeof(typename View::non_const_value_type);
    const auto recv = exchangeRows(host, rowBytes, sendOrder, sendCount, recvCount, mpi);
    View fresh = allocateField(spec.name, view, total, Initialize::no);  // every row copied below
    auto freshHost = Kokkos::create_mirror_view(fresh);
    const char* data = reinterpret_cast<const char*>(host.data());
    const auto source = [&](std::size_t k) {
      const std::size_t from = order[k];
      return from < kept ? data + staying[from] * rowBytes : recv.data() + (from - kept) * rowBytes;
    };
    // Runs of rows that lie one after the other in the source (most of the staying ones)
    // are copied as one block: a copy per row of a few bytes cost more than the bytes.
    char* out = reinterpret_cast<char*>(freshHost.data());
    for (std::size_t k = 0; k < total;) {
      const char* first = source(k);
      std::size_t end = k + 1;
      while (end < total && source(end) == first + (end - k) * rowBytes)
        ++end;
      std::copy(first, first + (end - k) * rowBytes, out + k * rowBytes);
      k = end;
    }
    Kokkos::deep_copy(fresh, freshHost);
    view = fresh;
  });
  if (particles.numMaterials() > 0)
    particles.indexMaterials(particles.numMaterials());
  return sendOrder.size();
}

template <int Dim>
std::size_t migrateToOwners(ParticleSet<Dim>& particles, const Decomposition<Dim>& decomposition,
                            const Comm& comm) {
  if (comm.getSize() == 1)
    return 0;  // one rank owns every cell: nothing to look up (a pass over the particles)
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
template std::size_t migrateParticles<3>(ParticleSet<3>&, const std::vector<int>&, const Comm&);
template std::size_t migrateToOwners<1>(ParticleSet<1>&, const Decomposition<1>&, const Comm&);
template std::size_t migrateToOwners<2>(ParticleSet<2>&, const Decomposition<2>&, const Comm&);
template std::size_t migrateToOwners<3>(ParticleSet<3>&, const Decomposition<3>&, const Comm&);

}  // namespace impm
