/* psd_info: the sizes of a PSD file as script variables, so that a scene can
   size its container from the soil.

     psd_info FILE [intervals N]

   Reads FILE as fix sequential/pack does (same format, same checks, same N
   equal-mass intervals, default 20) and defines the equal-style variables
     psd_dN   representative diameter of the coarsest interval (d_N)
     psd_d1   representative diameter of the finest interval (d_1)
     psd_d10, psd_d60, psd_Cu   of the PSD curve
   e.g. `variable L equal ${side}*${psd_dN}` gives a container `side`
   coarsest diameters wide for any soil (docs/user_guide.md). */

#ifdef COMMAND_CLASS

CommandStyle(psd_info,CommandPsdInfo)

#else

#ifndef LMP_COMMAND_PSD_INFO_H
#define LMP_COMMAND_PSD_INFO_H

#include "pointers.h"

namespace LAMMPS_NS {

class CommandPsdInfo : protected Pointers {
 public:
  explicit CommandPsdInfo(class LAMMPS *lmp) : Pointers(lmp) {}
  void command(int narg, char **arg);
};

}  // namespace LAMMPS_NS

#endif
#endif
