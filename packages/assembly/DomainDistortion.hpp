#pragma once
// How far the particles' integration domains have left their initial shape (gimp's boxes,
// cpdi's parallelograms).  D = R R0^-1 maps the initial domain (half-vectors R0, its columns)
// onto the current one (R); its distortion
//   delta = |D|_F |D^-1|_F / Dim
// is 1 for the initial shape scaled or turned, and grows as the domain is sheared or stretched
// more along one direction than across: in 2-D, delta = (s + 1/s) / 2 for principal stretches
// in the ratio s.  A distorted domain reaches far along its long direction through cells whose
// nodes it barely covers, and the weights of a parallelogram stop describing the material
// there (Sadeghirad, Brannon & Burghardt, IJNME 2011, introduced CPDI2's tracked corners for
// this).  The run warns once when a domain passes kDistortionWarning.

#include "core/ParticleSet.hpp"
#include "core/TpetraTypes.hpp"

namespace impm {

// delta above which the run warns: a domain about ten times longer than it is wide, relative
// to its initial shape (2-D and 3-D alike).
inline constexpr double kDistortionWarning = 5.0;

struct DomainDistortion {
  double worst = 1.0;      // the largest delta over the particles of every rank
  GlobalId particle = -1;  // the id of a particle that has it (-1: no particle)
  double smallestJ = 1.0;  // the smallest det D: the most compressed domain's volume ratio
};

// Collective.
template <int Dim, class Space = DefaultExecSpace>
DomainDistortion domainDistortion(const ParticleSet<Dim, Space>& particles, const Comm& comm);

}  // namespace impm
