#include "core/Collective.hpp"

#include <Teuchos_CommHelpers.hpp>

#include <algorithm>
#include <new>

#include "core/Errors.hpp"

namespace impm {

namespace {

enum Kind { kNone = 0, kInput = 1, kNumerical = 2, kOther = 3, kFile = 4, kMemory = 5 };

void broadcastString(const Comm& comm, int root, std::string& s) {
  int n = static_cast<int>(s.size());
  Teuchos::broadcast(comm, root, 1, &n);
  s.resize(n);
  if (n)
    Teuchos::broadcast(comm, root, n, &s[0]);
}

}  // namespace

void collectively(const Comm& comm, const std::function<void()>& phase) {
  int kind = kNone;
  std::string path, message;
  try {
    phase();
  } catch (const InputError& e) {
    kind = kInput, path = e.path(), message = e.what();
  } catch (const FileError& e) {
    kind = kFile, path = e.file(), message = e.what();
  } catch (const NumericalError& e) {
    kind = kNumerical, message = e.what();
  } catch (const std::bad_alloc& e) {
    kind = kMemory, message = e.what();
  } catch (const std::exception& e) {
    kind = kOther, message = e.what();
  }
  const int size = comm.getSize();
  const int mine = kind == kNone ? size : comm.getRank();
  int first = size;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MIN, mine, Teuchos::outArg(first));
  if (first == size)
    return;
  Teuchos::broadcast(comm, first, 1, &kind);
  broadcastString(comm, first, path);
  broadcastString(comm, first, message);
  if (kind == kInput) {
    // InputError's what() already starts with the path: keep the bare message.
    const std::string prefix = path.empty() ? "" : path + ": ";
    throw InputError(path, message.compare(0, prefix.size(), prefix) == 0
                               ? message.substr(prefix.size())
                               : message);
  }
  if (kind == kFile)
    throw FileError(path, message);
  if (kind == kNumerical)
    throw NumericalError(message);
  if (kind == kMemory)
    throw std::bad_alloc();
  throw std::runtime_error(message);
}

Teuchos::RCP<const Map> rootMap(GlobalId n, const Teuchos::RCP<const Comm>& comm) {
  const std::size_t local = comm->getRank() == 0 ? static_cast<std::size_t>(n) : 0;
  return Teuchos::rcp(new Map(static_cast<Tpetra::global_size_t>(n), local, 0, comm));
}

std::vector<double> gatherToAll(const Comm& comm, const std::vector<double>& local) {
  const int ranks = comm.getSize();
  const int count = static_cast<int>(local.size());
  std::vector<int> counts(ranks);
  Teuchos::gatherAll(comm, 1, &count, ranks, counts.data());
  const int widest = *std::max_element(counts.begin(), counts.end());
  std::vector<double> padded(local), gathered(static_cast<std::size_t>(widest) * ranks);
  padded.resize(widest);  // Teuchos gathers equal counts
  if (widest)
    Teuchos::gatherAll(comm, widest, padded.data(), widest * ranks, gathered.data());
  std::vector<double> all;
  for (int q = 0; q < ranks; ++q)
    all.insert(all.end(), gathered.begin() + q * widest, gathered.begin() + q * widest + counts[q]);
  return all;
}

bool onEveryRank(bool mine, const Comm& comm) {
  int local = mine ? 1 : 0, all = 0;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MIN, local, Teuchos::outArg(all));
  return all == 1;
}

}  // namespace impm
