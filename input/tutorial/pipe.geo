// A quarter of a pipe's cross-section (doc/tutorial.md): inner radius 1, outer radius 2,
// centred at the origin.  Quadrilaterals in a structured pattern: n_r across the wall, n_t
// around the quarter.  Mesh it with
//   gmsh -2 -format msh41 pipe.geo -o pipe.msh
// and a finer one with
//   gmsh -2 -format msh41 -setnumber n_r 8 -setnumber n_t 16 pipe.geo -o pipe_fine.msh
// (and n_r 16, n_t 32 for pipe_finer.msh)
DefineConstant[ n_r = 4, n_t = 8 ];

Point(1) = {0, 0, 0};  // the centre
Point(2) = {1, 0, 0};
Point(3) = {2, 0, 0};
Point(4) = {0, 2, 0};
Point(5) = {0, 1, 0};
Line(1) = {2, 3};       // on the x axis
Circle(2) = {3, 1, 4};  // the outer surface
Line(3) = {4, 5};       // on the y axis
Circle(4) = {5, 1, 2};  // the inner surface
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};

Transfinite Curve{1, 3} = n_r + 1;
Transfinite Curve{2, 4} = n_t + 1;
Transfinite Surface{1};
Recombine Surface{1};  // quadrilaterals, not triangles

// The names the deck uses: the element block, and the side sets for the loads.
Physical Surface("pipe") = {1};
Physical Curve("inner") = {4};
Physical Curve("outer") = {2};
Physical Curve("x0") = {3};
Physical Curve("y0") = {1};
