#pragma once
// One Exodus II file: a mesh (one element block) with nodal, element and global variables,
// one time step per output step.  The file is reopened and closed for every step, so a run
// that stops early leaves a readable file with the steps written so far.  Serial: the
// caller gathers the data to one rank.

#include <string>
#include <vector>

namespace impm {

struct ExodusMesh {
  int dimension = 1;                        // spatial dimension of the coordinates
  std::vector<std::vector<double>> coords;  // coords[d][node]
  std::string elementType;                  // BAR2, QUAD4, SPHERE (one-node elements)
  int nodesPerElement = 1;
  std::vector<int> connectivity;  // 1-based node numbers, nodesPerElement per element
  std::vector<int> elementIds;    // optional element numbering (1-based ids)

  std::size_t numNodes() const { return coords.empty() ? 0 : coords[0].size(); }
  std::size_t numElements() const { return connectivity.size() / nodesPerElement; }
};

class ExodusFile {
 public:
  // Creates (overwrites) the file.  Throws FileError naming the file and the reason.
  // With keepSteps > 0 (a restart) the file is continued instead: an existing file of this
  // mesh and these variables keeps its first keepSteps time steps (later ones, written
  // after the checkpoint, are dropped by a copy); if there is none, or it does not fit, a
  // new file is made (continued() says which).
  ExodusFile(const std::string& path, const std::string& title, const ExodusMesh& mesh,
             const std::vector<std::string>& nodalVariables,
             const std::vector<std::string>& elementVariables,
             const std::vector<std::string>& globalVariables, int keepSteps = 0);

  // Appends time step `time`; values[variable][node or element].  FileError when it cannot.
  void append(double time, const std::vector<std::vector<double>>& nodal,
              const std::vector<std::vector<double>>& element, const std::vector<double>& global);

  const std::string& path() const { return path_; }
  int stepsWritten() const { return steps_; }
  bool continued() const { return continued_; }

 private:
  void create(const std::string& path, const std::string& title, const ExodusMesh& mesh,
              const std::vector<std::string>& nodal, const std::vector<std::string>& element,
              const std::vector<std::string>& global) const;
  // Copies the first `steps` time steps of `from` into the (new) file at path_; false when
  // `from` does not have this mesh's sizes and variables or fewer steps.
  bool copySteps(const std::string& from, int steps) const;
  std::string path_;
  std::size_t numNodes_, numElements_;
  std::size_t numNodal_, numElement_, numGlobal_;
  int steps_ = 0;
  bool continued_ = false;
};

}  // namespace impm
