#include "app/shapes/ShapeFactory.hpp"

#include <algorithm>
#include <functional>
#include <type_traits>

#include "app/shapes/Ball.hpp"
#include "app/shapes/Box.hpp"
#include "app/shapes/Cylinder.hpp"
#include "app/shapes/Extrusion.hpp"
#include "app/shapes/Image.hpp"
#include "app/shapes/Interval.hpp"
#include "app/shapes/Mesh.hpp"
#include "app/shapes/Polygon.hpp"
#include "app/shapes/VoxelStack.hpp"
#include "core/Errors.hpp"
#include "core/Parameters.hpp"

namespace impm {

namespace {

template <int Dim>
using Creator = std::function<std::shared_ptr<const Shape<Dim>>(const Teuchos::ParameterList&,
                                                                const std::string&)>;

struct Entry {
  std::string name;
  int dimension;
  std::function<void(Teuchos::ParameterList&)> declare;
  Creator<1> create1;  // the one of the shape's dimension is set
  Creator<2> create2;
  Creator<3> create3;
};

template <class S>
constexpr int dimensionOf() {
  return std::is_base_of_v<Shape<1>, S> ? 1 : (std::is_base_of_v<Shape<2>, S> ? 2 : 3);
}

template <class S>
Entry entry(const std::string& name) {
  constexpr int dim = dimensionOf<S>();
  Entry e{name, dim, &S::declareParameters, {}, {}, {}};
  const auto make = [](const Teuchos::ParameterList& p, const std::string& path) {
    return std::make_shared<const S>(p, path);
  };
  if constexpr (dim == 1)
    e.create1 = make;
  else if constexpr (dim == 2)
    e.create2 = make;
  else
    e.create3 = make;
  return e;
}

// The registration lines: one per shape.
const std::vector<Entry>& registry() {
  static const std::vector<Entry> shapes = {
      entry<Interval>("interval"), entry<Box<2>>("rectangle"), entry<Ball<2>>("disk"),
      entry<Polygon>("polygon"),   entry<Image>("image"),      entry<Mesh>("mesh"),
      entry<Box<3>>("box"),        entry<Ball<3>>("sphere"),   entry<Cylinder>("cylinder"),
      entry<VoxelStack>("image"),  // a name of two dimensions: the deck's picks the one
  };
  return shapes;
}

// The 2-D shape extruded along z over the deck's Extrusion.
std::shared_ptr<const Shape<3>> extrusion(std::shared_ptr<const Shape<2>> base,
                                          const Teuchos::ParameterList& params,
                                          const std::string& path) {
  const auto& z = params.get<Teuchos::Array<double>>("Extrusion");
  if (!(z[0] < z[1]))
    throw InputError(path + "/Extrusion", "expected z0 < z1, got {" + std::to_string(z[0]) + ", " +
                                              std::to_string(z[1]) + "}");
  return std::make_shared<const Extrusion>(std::move(base), z[0], z[1]);
}

}  // namespace

void declareShapeParameters(Teuchos::ParameterList& valid) {
  std::vector<std::string> names;
  for (const auto& e : registry())
    if (std::find(names.begin(), names.end(), e.name) == names.end())
      names.push_back(e.name);
  declareChoice(valid, "Shape", "interval", names,
                "Geometry of the body in the reference configuration: interval (1-D); "
                "rectangle, disk, polygon, image or mesh (2-D; in a 3-D deck extruded along z, "
                "see Extrusion); box, sphere, cylinder or image (3-D: a stack of slices)");
  declareDoubleArray(valid, "Extrusion", {0.0, 1.0}, {2},
                     "3-D decks with a 2-D shape: {z0, z1}, the shape extruded along z from z0 to "
                     "z1 (filled on sub-cells like the 3-D shapes)");
  for (const auto& e : registry())
    e.declare(valid.sublist("[Shape=" + e.name + "]"));
}

template <int Dim>
std::shared_ptr<const Shape<Dim>> createShape(const Teuchos::ParameterList& params,
                                              const std::string& path) {
  const auto& name = params.get<std::string>("Shape");
  const bool extruded = setInDeck(params, "Extrusion");
  // A name may stand for shapes of two dimensions (image): the one of the deck's, or of the
  // 2-D outline it extrudes.
  const int wanted = extruded ? 2 : Dim;
  const Entry* chosen = nullptr;
  for (const auto& e : registry())
    if (e.name == name && (!chosen || e.dimension == wanted))
      chosen = &e;
  if (!chosen)
    throw std::logic_error("unregistered shape " + name);
  const Entry& e = *chosen;
  if (extruded && (Dim != 3 || e.dimension != 2))
    throw InputError(path + "/Extrusion", "extrudes a 2-D shape in a 3-D deck; shape '" + name +
                                              "' is " + std::to_string(e.dimension) +
                                              "-D and the grid " + std::to_string(Dim) + "-D");
  if constexpr (Dim == 3)
    if (extruded)
      return extrusion(e.create2(params, path), params, path);
  if (e.dimension != Dim)
    throw InputError(
        path + "/Shape",
        "shape '" + name + "' is " + std::to_string(e.dimension) + "-D but the grid is " +
            std::to_string(Dim) + "-D" +
            (Dim == 3 && e.dimension == 2 ? " (give Extrusion = {z0, z1} to extrude it along z)"
                                          : ""));
  if constexpr (Dim == 1)
    return e.create1(params, path);
  else if constexpr (Dim == 2)
    return e.create2(params, path);
  else
    return e.create3(params, path);
}

template std::shared_ptr<const Shape<1>> createShape<1>(const Teuchos::ParameterList&,
                                                        const std::string&);
template std::shared_ptr<const Shape<2>> createShape<2>(const Teuchos::ParameterList&,
                                                        const std::string&);
template std::shared_ptr<const Shape<3>> createShape<3>(const Teuchos::ParameterList&,
                                                        const std::string&);

}  // namespace impm
