/* error: stop the run with a LIGGGHTS error that says what is wrong.

     error "message"

   LIGGGHTS 3.8 scripts can test a condition (`if`) but cannot fail: `quit`
   ends with exit status 0 and `print` only prints. `error` calls
   error->all with the message, so every rank stops, the screen and the log
   show "ERROR: message", and the exit status is not 0. Used as
     if "${dt} > ${dt_crit}" then "error 'the time step ... is above ...'"
   (docs/user_guide.md, "When it stops with an error"). */

#ifdef COMMAND_CLASS

CommandStyle(error,CommandError)

#else

#ifndef LMP_COMMAND_ERROR_H
#define LMP_COMMAND_ERROR_H

#include "pointers.h"

namespace LAMMPS_NS {

class CommandError : protected Pointers {
 public:
  explicit CommandError(class LAMMPS *lmp) : Pointers(lmp) {}
  void command(int narg, char **arg);
};

}  // namespace LAMMPS_NS

#endif
#endif
