// liggghts-fabric: the `liggghts` executable with this project's styles.
//
// LIGGGHTS 3.8 has no plugin loader; Modify and Input keep their style maps
// private.
// An explicit template instantiation may name a private member (C++17
// [temp.explicit]/12), which yields a pointer-to-member through which the
// launcher adds our creators to the maps after LAMMPS is constructed and
// before the input is read. Everything else is LIGGGHTS' own main() (the
// LAMMPS constructor parses -in -var -log -echo -screen itself), plus the
// output guarantees below.
//
// Errors that reach the output. LIGGGHTS' error->one (a missing `include`
// file, a neighbour-list overflow, out of memory, an error found on one
// rank) prints "ERROR on proc N: ..." to the screen and calls MPI_Abort,
// which kills the processes without flushing their stdio buffers: with the
// output redirected to a file (a batch job) the ERROR line and the log file
// were lost, the log often left at 0 bytes. The launcher therefore
//   * line-buffers stdout (every rank's screen) before anything is printed,
//     and the screen and log files once LAMMPS has opened them, so a process
//     killed by another rank's abort has still written every whole line;
//   * intercepts MPI_Abort through the MPI profiling interface (the
//     standard's PMPI_ names) to flush every open stream before aborting.
#include <mpi.h>

#include <cstdio>
#include <map>
#include <string>

#include "compute.h"
#include "fix.h"
#include "input.h"
#include "lammps.h"
#include "modify.h"
#include "universe.h"
#include "styles.h"

using namespace LAMMPS_NS;

namespace {

using FixCreator = Fix *(*)(LAMMPS *, int, char **);
using ComputeCreator = Compute *(*)(LAMMPS *, int, int, char **);
using FixMap = std::map<std::string, FixCreator> *Modify::*;
using ComputeMap = std::map<std::string, ComputeCreator> *Modify::*;
using CommandCreator = void (*)(LAMMPS *, int, char **);
using CommandMap = std::map<std::string, CommandCreator> *Input::*;

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
struct CommandMapTag {
  using type = CommandMap;
  friend type member(CommandMapTag);
};
template struct Expose<FixMapTag, &Modify::fix_map>;
template struct Expose<CommandMapTag, &Input::command_map>;
template struct Expose<ComputeMapTag, &Modify::compute_map>;

LAMMPS *the_lammps = nullptr;  // for the abort hook

// Line-buffer a stream LAMMPS has opened (and may have written to already:
// glibc's setvbuf keeps the pending output and only changes the mode).
void line_buffer(FILE *f) {
  if (f && f != stdout && f != stderr) setvbuf(f, nullptr, _IOLBF, 0);
}

void flush_everything() {
  if (the_lammps) {
    for (FILE *f : {the_lammps->screen, the_lammps->logfile,
                    the_lammps->universe->uscreen,
                    the_lammps->universe->ulogfile})
      if (f) fflush(f);
  }
  fflush(nullptr);  // every other open output stream, stdout included
}

void register_styles(LAMMPS *lmp) {
  auto &fixes = *(lmp->modify->*member(FixMapTag()));
  auto &computes = *(lmp->modify->*member(ComputeMapTag()));
  for (const auto &s : fabric_styles::fixes()) fixes[s.first] = s.second;
  for (const auto &s : fabric_styles::computes()) computes[s.first] = s.second;
  auto &commands = *(lmp->input->*member(CommandMapTag()));
  for (const auto &s : fabric_styles::commands()) commands[s.first] = s.second;
}

}  // namespace

// MPI's profiling interface: this definition replaces the library's
// MPI_Abort for the whole process (LIGGGHTS included), PMPI_Abort is the
// real one.
extern "C" int MPI_Abort(MPI_Comm comm, int errorcode) {
  flush_everything();
  return PMPI_Abort(comm, errorcode);
}

int main(int argc, char **argv) {
  // Before any output: whole lines reach a redirected stdout at once.
  setvbuf(stdout, nullptr, _IOLBF, BUFSIZ);
  setvbuf(stderr, nullptr, _IONBF, 0);
  MPI_Init(&argc, &argv);
  LAMMPS *lmp = new LAMMPS(argc, argv, MPI_COMM_WORLD);
  the_lammps = lmp;
  for (FILE *f : {lmp->screen, lmp->logfile, lmp->universe->uscreen,
                  lmp->universe->ulogfile})
    line_buffer(f);
  register_styles(lmp);
  lmp->input->file();
  the_lammps = nullptr;
  delete lmp;
  MPI_Finalize();
  return 0;
}
