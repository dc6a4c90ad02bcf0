#include "command_error.h"

#include <cstring>
#include <string>

#include "error.h"
#include "input.h"
#include "memory.h"

using namespace LAMMPS_NS;

void CommandError::command(int narg, char **arg) {
  if (narg < 1)
    error->all(FLERR, "error: give the message to stop with, e.g. error \"the time step is too large\"");
  std::string message = arg[0];
  for (int i = 1; i < narg; ++i) message += std::string(" ") + arg[i];
  // The message comes quoted, where LIGGGHTS leaves $x and ${name} alone (as
  // inside an `if` command): substitute them here, as `print` does, so the
  // message can name the offending value.
  int max = static_cast<int>(message.size()) + 1, max2 = max;
  char *text = static_cast<char *>(memory->smalloc(max, "error:text"));
  char *work = static_cast<char *>(memory->smalloc(max2, "error:work"));
  std::strcpy(text, message.c_str());
  input->substitute(text, work, max, max2, 0);
  message = text;
  memory->sfree(text);
  memory->sfree(work);
  error->all(FLERR, message.c_str());
}
