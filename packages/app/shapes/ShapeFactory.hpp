#pragma once
// Bodies/<name>/Shape: the shapes a deck can name, their parameters ("[Shape=...]"
// sublists) and their construction.  Adding a shape = one class (Shape.hpp) and one line
// in ShapeFactory.cpp.

#include <Teuchos_ParameterList.hpp>

#include <memory>

#include "app/shapes/Shape.hpp"

namespace impm {

// Shape, and the parameters of each shape in "[Shape=...]" sublists.
void declareShapeParameters(Teuchos::ParameterList& valid);

// The shape of Bodies/<name> (path); throws InputError naming path + "/<parameter>" when the
// shape is degenerate or is not a Dim-D shape.
template <int Dim>
std::shared_ptr<const Shape<Dim>> createShape(const Teuchos::ParameterList& params,
                                              const std::string& path);

}  // namespace impm
