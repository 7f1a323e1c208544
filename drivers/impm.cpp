// impm: the driver.  Reads an XML deck, checks it, runs it, writes the outputs.
//
//   impm [--output-dir DIR] [--restart CHECKPOINT] [--set Path/To/Param=value]... deck.xml
//   impm --list-parameters
//   impm --help
//
// Exit status: 0 success; 1 bad input or checkpoint (nothing written), or an output that
// could not be written; 2 bad command line; 3 numerical failure (outputs so far are
// readable); 4 a verification check failed; 5 stopped by SIGINT, SIGTERM or SIGUSR1 after
// writing a checkpoint.

#include <Tpetra_Core.hpp>

#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <new>
#include <string>
#include <vector>

#include "app/AppParameters.hpp"
#include "app/Simulation.hpp"
#include "core/Collective.hpp"
#include "core/Errors.hpp"
#include "core/MemoryPolicy.hpp"
#include "core/Parameters.hpp"
#include "core/StopRequest.hpp"
#include "io/InputDeck.hpp"
#include "io/Version.hpp"

namespace {

const char* kUsage =
    "usage: impm [--output-dir DIR] [--restart CHECKPOINT [--allow-physics-change]]\n"
    "            [--set Path/To/Param=value]... [--verbose | --quiet] deck.xml\n"
    "       impm --list-parameters | --version\n"
    "       impm --help\n"
    "\n"
    "Runs the implicit MPM/FEM problem described by the Teuchos XML deck.\n"
    "  --output-dir DIR   write the outputs to DIR (default: the deck's Output/Directory)\n"
    "  --restart FILE     continue the run from a checkpoint FILE the same deck wrote\n"
    "                     (Output/Checkpoint Every); run controls may change with --set\n"
    "                     (Output, Solver, Verification, Load Balance, Final Time)\n"
    "  --allow-physics-change  a restart may also change what defines the problem (a\n"
    "                     modulus, a boundary value, the time step); each change is printed\n"
    "  --set P=V          override parameter P (a path such as Grid/Cells) with value V,\n"
    "                     typed like P; arrays in Teuchos syntax: --set Grid/Cells={64}\n"
    "  --verbose          print every step and every Newton iteration\n"
    "  --quiet            print only errors, warnings and the final summary (by default:\n"
    "                     a line per step while steps take a second or more, otherwise\n"
    "                     one every few seconds, with the time elapsed and left)\n"
    "  --list-parameters  print every deck parameter with its type, default and meaning\n"
    "  --version          print impm's version and commit and the libraries' versions\n"
    "  --kokkos-help      print the options of Kokkos (--kokkos-*), which impm passes on\n"
    "On SIGINT, SIGTERM or SIGUSR1 impm writes a checkpoint of the last finished step, prints\n"
    "how to continue from it, and exits with status 5 (a second signal stops it at once;\n"
    "under mpirun send SIGUSR1, which mpirun passes on at once).\n"
    "Exit status: 0 success, 1 bad input, checkpoint or failed write, 2 bad command line,\n"
    "3 numerical failure, 4 failed verification check, 5 stopped by a signal.\n";

// After a command-line error: the usage's first lines, not the page of options.
std::string synopsis() {
  const std::string usage = kUsage;
  return usage.substr(0, usage.find("\n\n") + 1) + "Run impm --help for the options.\n";
}

struct Arguments {
  std::string deck, outputDirectory, restart;
  std::vector<impm::Override> overrides;
  bool list = false, version = false;
  bool allowPhysicsChange = false;
  impm::Verbosity verbosity = impm::Verbosity::normal;
};

// A message cut to a length a terminal and a log can hold: a user's value echoed in an
// error (a 10^7-character --set) is kept by its start and its end.
std::string shortened(const std::string& message) {
  constexpr std::size_t kHead = 1500, kTail = 300;
  if (message.size() <= kHead + kTail + 100)
    return message;
  return message.substr(0, kHead) + " ... (" + std::to_string(message.size() - kHead - kTail) +
         " characters cut) ... " + message.substr(message.size() - kTail);
}

// An option's value; an empty one (--output-dir '') was ignored silently.
std::string nonEmpty(const std::string& option, const std::string& value) {
  if (value.empty())
    throw impm::InputError("", option + " needs a value, got an empty one");
  return value;
}

Arguments parse(int argc, char** argv) {
  Arguments a;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    auto value = [&](const std::string& option) {
      if (i + 1 >= argc)
        throw impm::InputError("", option + " needs a value");
      return nonEmpty(option, argv[++i]);
    };
    if (arg == "--list-parameters")
      a.list = true;
    else if (arg == "--version")
      a.version = true;
    else if (arg == "--verbose")
      a.verbosity = impm::Verbosity::verbose;
    else if (arg == "--quiet")
      a.verbosity = impm::Verbosity::quiet;
    else if (arg == "--allow-physics-change")
      a.allowPhysicsChange = true;
    else if (arg == "--output-dir")
      a.outputDirectory = value(arg);
    else if (arg.rfind("--output-dir=", 0) == 0)
      a.outputDirectory = nonEmpty("--output-dir", arg.substr(13));
    else if (arg == "--restart")
      a.restart = value(arg);
    else if (arg.rfind("--restart=", 0) == 0)
      a.restart = nonEmpty("--restart", arg.substr(10));
    else if (arg == "--set")
      a.overrides.push_back(impm::parseOverride(value(arg)));
    else if (arg.rfind("--set=", 0) == 0)
      a.overrides.push_back(impm::parseOverride(arg.substr(6)));
    else if (!arg.empty() && arg[0] == '-')
      throw impm::InputError("", "unknown option " + arg);
    else if (a.deck.empty())
      a.deck = arg;
    else
      throw impm::InputError("", "more than one deck given (" + a.deck + ", " + arg + ")");
  }
  if (!a.list && !a.version && a.deck.empty())
    throw impm::InputError("", "no deck given");
  return a;
}

// The command line that continues a stopped run: this one, restarting from `checkpoint` (a
// run under mpirun needs the same launcher in front of it).
std::string continueCommand(int argc, char** argv, const std::string& checkpoint) {
  const auto quoted = [](const std::string& a) {
    if (!a.empty() && a.find_first_of(" \t'\"\\$`!*?{}[]()<>|&;") == std::string::npos)
      return a;
    std::string q = "'";
    for (char c : a)
      q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
  };
  std::string line = quoted(argv[0]) + " --restart " + quoted(checkpoint);
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--restart") {
      ++i;  // and its value
      continue;
    }
    if (arg.rfind("--restart=", 0) == 0)
      continue;
    line += " " + quoted(arg);
  }
  return line;
}

template <int Dim>
int runDeck(const Teuchos::ParameterList& deck, const Arguments& args,
            const Teuchos::RCP<const impm::Comm>& comm) {
  impm::Simulation<Dim> simulation(deck, args.deck, args.outputDirectory, comm, args.restart,
                                   args.verbosity, args.allowPhysicsChange);
  const auto failures = simulation.run();
  if (failures.empty())
    return 0;
  if (comm->getRank() == 0)
    for (const auto& f : failures)
      std::cerr << "impm: verification failed: " << f << "\n";
  return 4;
}

// A run on one node needs no network.  Ranks that mpirun starts on this node take the
// shared-memory transport; Open MPI otherwise sets up its TCP transport first (0.2 s of a
// 2-rank start).  A run started without a launcher (no mpirun: one rank) needs no runtime
// daemon either: Open MPI's singleton start-up otherwise probes every transport (0.3 s) and
// starts a daemon (0.13 s), of a 1-D deck's 0.7 s.  An isolated singleton takes the same
// session directory as every other one, and two runs at once then broke each other's MPI-IO
// files, so each gets its own directory, removed at exit.  Only unset variables are set, so
// a user's choice stands (over Open MPI's parameter files, these variables win); other MPI
// libraries ignore them.
class QuietMpiStart {
 public:
  QuietMpiStart() {
    if (allRanksOnThisNode()) {
      setenv("OMPI_MCA_pml", "ob1", 0);  // shared memory between ranks (and to itself) only
      setenv("OMPI_MCA_btl", "self,vader", 0);
    }
    if (launched())
      return;
    if (std::getenv("OMPI_MCA_ess_singleton_isolated") || std::getenv("OMPI_MCA_orte_tmpdir_base"))
      return;
    std::error_code error;
    const auto temp = std::filesystem::temp_directory_path(error);
    if (error)
      return;
    removeStale(temp);
    const auto dir = temp / (kPrefix + std::to_string(getpid()));
    if (!std::filesystem::create_directory(dir, error) || error)
      return;  // then the daemon stays: slower, not wrong
    sessions_ = dir;
    setenv("OMPI_MCA_orte_tmpdir_base", dir.c_str(), 1);
    setenv("OMPI_MCA_ess_singleton_isolated", "1", 1);
  }
  ~QuietMpiStart() {  // after MPI_Finalize
    std::error_code ignored;
    if (!sessions_.empty())
      std::filesystem::remove_all(sessions_, ignored);
  }
  QuietMpiStart(const QuietMpiStart&) = delete;
  QuietMpiStart& operator=(const QuietMpiStart&) = delete;

 private:
  static constexpr const char* kPrefix = "impm-singleton-";

  // Started by a launcher (mpirun or a PMI one), not as a singleton.
  static bool launched() {
    for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE"})
      if (std::getenv(name))
        return true;
    return false;
  }

  // A singleton, or every rank started by Open MPI's mpirun on this node: then no rank needs
  // a network.  Every rank sees the same two numbers, so all make the same choice.
  static bool allRanksOnThisNode() {
    if (!launched())
      return true;
    const char* size = std::getenv("OMPI_COMM_WORLD_SIZE");
    const char* local = std::getenv("OMPI_COMM_WORLD_LOCAL_SIZE");
    return size && local && std::string(size) == local;
  }

  // The directories of runs that were killed (SIGKILL leaves no time to remove them): those
  // whose process no longer exists.
  static void removeStale(const std::filesystem::path& temp) {
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator(temp, error)) {
      const std::string name = entry.path().filename().string();
      if (name.rfind(kPrefix, 0) != 0)
        continue;
      const std::string digits = name.substr(std::string(kPrefix).size());
      if (digits.empty() || digits.size() > 9 ||
          digits.find_first_not_of("0123456789") != std::string::npos)
        continue;
      if (kill(static_cast<pid_t>(std::stol(digits)), 0) != 0 && errno == ESRCH)
        std::filesystem::remove_all(entry.path(), error);
    }
  }

  std::filesystem::path sessions_;
};

}  // namespace

int main(int argc, char** argv) {
  impm::keepFreedMemory();         // before any allocation
  impm::ignoreFileSizeSignal();    // a write past ulimit -f fails with a message
  const QuietMpiStart quietStart;  // before MPI starts, removed after it ends
  // Kokkos::initialize takes --help too and prints its own options: impm's --help prints
  // impm's usage only, and Kokkos' stays reachable as --kokkos-help.
  bool help = false, kokkosHelp = false;
  std::vector<char*> kept;
  for (int i = 0; i < argc; ++i) {
    const std::string arg = argv[i];
    if (i > 0 && (arg == "--help" || arg == "-h"))
      help = true;
    else
      kept.push_back(argv[i]);
    kokkosHelp = kokkosHelp || arg == "--kokkos-help";
  }
  int keptCount = static_cast<int>(kept.size());
  kept.push_back(nullptr);
  char** keptArgs = kept.data();
  Tpetra::ScopeGuard scope(&keptCount, &keptArgs);  // removes the --kokkos-* options
  impm::adviseHugePages();                          // once Kokkos can report its allocations
  auto comm = Tpetra::getDefaultComm();
  impm::installStopHandlers();  // after MPI and Kokkos, so that theirs do not replace impm's
  const bool root = comm->getRank() == 0;
  if (kokkosHelp)
    return 0;  // Kokkos printed its help
  if (help) {
    if (root)
      std::cout << kUsage;
    return 0;
  }
  Arguments args;
  try {
    args = parse(keptCount, keptArgs);
  } catch (const impm::InputError& e) {
    if (root)
      std::cerr << "impm: error: " << shortened(e.what()) << "\n" << synopsis();
    return 2;
  }
  if (args.version) {
    if (root)
      std::cout << impm::versionText();
    return 0;
  }
  const auto valid = impm::deckValidParameters();
  if (args.list) {
    if (root)
      impm::listParameters(valid, std::cout);
    return 0;
  }
  try {
    Teuchos::ParameterList deck;
    impm::collectively(*comm, [&] { deck = impm::loadDeck(args.deck, args.overrides, valid); });
    const auto dim = deck.sublist("Grid").get<Teuchos::Array<int>>("Cells").size();
    if (dim == 1)
      return runDeck<1>(deck, args, comm);
    if (dim == 2)
      return runDeck<2>(deck, args, comm);
    return runDeck<3>(deck, args, comm);  // the validator allows 1 to 3 entries
  } catch (const impm::InputError& e) {
    if (root)
      std::cerr << "impm: error: " << args.deck << ": " << shortened(e.what()) << "\n";
    return 1;
  } catch (const impm::FileError& e) {
    if (root)
      std::cerr << "impm: error: " << e.file() << ": " << shortened(e.what()) << "\n";
    return 1;
  } catch (const impm::NumericalError& e) {
    if (root)
      std::cerr << "impm: numerical failure: " << shortened(e.what()) << "\n";
    return 3;
  } catch (const impm::RunStopped& e) {
    if (root)
      std::cerr << "impm: " << e.what() << " (t = " << e.time()
                << (e.abandoned() ? "; step " + std::to_string(e.step() + 1) + " was abandoned"
                                  : "")
                << "): checkpoint " << e.checkpoint()
                << "; continue with: " << continueCommand(keptCount, keptArgs, e.checkpoint())
                << "\n";
    return impm::kStoppedExit;
  } catch (const std::bad_alloc&) {
    if (root)
      std::cerr << "impm: error: " << args.deck
                << ": not enough memory for this problem (its grid, Grid/Cells, and the particles "
                   "its bodies make)\n";
    return 1;
  } catch (const std::exception& e) {  // not foreseen: still one line, naming the deck
    if (root)
      std::cerr << "impm: error: " << args.deck << ": "
                << shortened(impm::trilinosMessage(e.what())) << "\n";
    return 3;
  }
}
