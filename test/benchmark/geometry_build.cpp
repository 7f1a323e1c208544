// The cost of making particles from geometry files: reads an image or a mesh as one body
// and creates its cpdi particles on one rank, as impm does before a run.  Prints one line,
//   particles <n> seconds <t> peak_kB_per_particle <m>
// where t covers reading the file and creating the particles, and m is the growth of the
// process's peak resident memory over that time divided by the particle count.
//
//   geometry_build image FILE.png PIXEL_SIZE LOWEST HIGHEST LENGTH CELLS
//   geometry_build mesh FILE.exo LENGTH CELLS
// The grid is the square [0, LENGTH]^2 in CELLS x CELLS cells; the image's lower-left corner
// is at the origin.

#include <Teuchos_DefaultComm.hpp>
#include <Tpetra_Core.hpp>

#include <sys/resource.h>

#include <chrono>
#include <iostream>
#include <string>

#include "app/Bodies.hpp"
#include "core/NodeOwnership.hpp"
#include "core/Parameters.hpp"
#include "material/MaterialFactory.hpp"

namespace {

double peakKilobytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss);  // Linux: kB
}

}  // namespace

int main(int argc, char** argv) {
  Tpetra::ScopeGuard scope(&argc, &argv);
  const std::string kind = argc > 1 ? argv[1] : "";
  if (!((kind == "image" && argc == 8) || (kind == "mesh" && argc == 5))) {
    std::cerr << "usage: geometry_build image FILE PIXEL LOWEST HIGHEST LENGTH CELLS\n"
                 "       geometry_build mesh FILE LENGTH CELLS\n";
    return 2;
  }
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  Teuchos::ParameterList deck;
  auto& mat = deck.sublist("Materials").sublist("solid");
  mat.set("Model", std::string("neo-hookean")), mat.set("E", 1.0), mat.set("nu", 0.3);
  mat.set("Density", 1.0);
  impm::validateParameters(mat, impm::materialValidParameters());
  auto& body = deck.sublist("Bodies").sublist("body");
  body.set("Material", std::string("solid"));
  body.set("Shape", kind);
  if (kind == "image") {
    body.set("Image File", std::string(argv[2]));
    body.set("Pixel Size", std::stod(argv[3]));
    body.set("Image Origin", Teuchos::Array<double>(std::vector<double>{0.0, 0.0}));
    body.set("Gray Range",
             Teuchos::Array<int>(std::vector<int>{std::stoi(argv[4]), std::stoi(argv[5])}));
  } else {
    body.set("Mesh File", std::string(argv[2]));
  }
  impm::validateParameters(body, impm::bodyValidParameters());
  const double length = std::stod(argv[argc - 2]);
  const int cells = std::stoi(argv[argc - 1]);
  try {
    const auto start = std::chrono::steady_clock::now();
    const double before = peakKilobytes();
    impm::NodeOwnership<2> own(
        impm::makeGridGeometry<2>({0.0, 0.0}, {length, length}, {cells, cells}), comm);
    impm::Bodies<2> bodies(deck, {"solid"}, own.grid());
    std::vector<std::shared_ptr<impm::Material<2>>> materials = {
        impm::createMaterial<2>("solid", mat)};
    const auto particles = bodies.createParticles(impm::Method::cpdi, own.decomposition(),
                                                  comm->getRank(), materials, true);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double grown = peakKilobytes() - before;
    std::cout << "particles " << particles.size() << " seconds " << seconds
              << " peak_kB_per_particle " << grown / particles.size() << "\n";
  } catch (const std::exception& e) {
    std::cerr << "geometry_build: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
