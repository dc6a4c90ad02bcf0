// liggghts-fabric: the `liggghts` executable with this project's styles.
//
// LIGGGHTS 3.8 has no plugin loader and Modify keeps its style maps private.
// An explicit template instantiation may name a private member (C++17
// [temp.explicit]/12), which yields a pointer-to-member through which the
// launcher adds our creators to the maps after LAMMPS is constructed and
// before the input is read. Everything else is exactly LIGGGHTS' own main():
// the LAMMPS constructor parses -in -var -log -echo -screen itself.
#include <mpi.h>

#include <map>
#include <string>

#include "compute.h"
#include "fix.h"
#include "input.h"
#include "lammps.h"
#include "modify.h"
#include "styles.h"

using namespace LAMMPS_NS;

namespace {

using FixCreator = Fix *(*)(LAMMPS *, int, char **);
using ComputeCreator = Compute *(*)(LAMMPS *, int, int, char **);
using FixMap = std::map<std::string, FixCreator> *Modify::*;
using ComputeMap = std::map<std::string, ComputeCreator> *Modify::*;

// The "access a private member" idiom: the friend function defined in the
// explicitly instantiated template returns the member pointer.
template <typename Tag, typename Tag::type Member>
struct Expose {
  friend typename Tag::type member(Tag) { return Member; }
};
struct FixMapTag {
  using type = FixMap;
  friend type member(FixMapTag);
};
struct ComputeMapTag {
  using type = ComputeMap;
  friend type member(ComputeMapTag);
};
template struct Expose<FixMapTag, &Modify::fix_map>;
template struct Expose<ComputeMapTag, &Modify::compute_map>;

void register_styles(LAMMPS *lmp) {
  auto &fixes = *(lmp->modify->*member(FixMapTag()));
  auto &computes = *(lmp->modify->*member(ComputeMapTag()));
  for (const auto &s : fabric_styles::fixes()) fixes[s.first] = s.second;
  for (const auto &s : fabric_styles::computes()) computes[s.first] = s.second;
}

}  // namespace

int main(int argc, char **argv) {
  MPI_Init(&argc, &argv);
  LAMMPS *lmp = new LAMMPS(argc, argv, MPI_COMM_WORLD);
  register_styles(lmp);
  lmp->input->file();
  delete lmp;
  MPI_Finalize();
  return 0;
}
