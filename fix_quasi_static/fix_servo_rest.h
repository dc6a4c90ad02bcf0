/* fix servo/rest: the quasi-static loading protocol (see
   docs/fix_servo_rest.md). A servo wall loads the group until its stress
   is on target and the grains nearly balanced, the wall is held and the
   grains relaxed until the unbalanced-force ratio of a fix quasi/static
   calls rest; a relaxed stress off the target gives the wall back to the
   servo. A thin adapter: the protocol is core/rest_protocol.* (no
   LIGGGHTS include). The fix decides at the end of the steps the protocol
   names and tells the script how long to run (f_ID[2]); its state goes
   into restart files, so that a checkpointed loading goes on. */

#ifdef FIX_CLASS

FixStyle(servo/rest,FixServoRest)

#else

#ifndef LMP_FIX_SERVO_REST_H
#define LMP_FIX_SERVO_REST_H

#include <memory>
#include <string>

#include "fix.h"
#include "rest_protocol.h"

namespace LAMMPS_NS {

class FixServoRest : public Fix {
 public:
  FixServoRest(class LAMMPS *, int, char **);
  int setmask();
  void init();
  void setup(int);
  void end_of_step();
  double compute_vector(int i);
  void write_restart(FILE *);
  void restart(char *);

 private:
  void read_keywords(int narg, char **arg);
  void find_fixes();
  double target_stress();
  double lid_stress();
  double kinetic_energy();
  void say(const std::string &line);

  std::string lid_id_, qs_id_, stress_var_;
  double stress_ = 0.0;    // constant target stress (Pa), or ...
  int stress_ivar_ = -1;   // ... an equal-style variable's index
  double area_ = 0.0;
  double ke_vrms_ = 0.0;   // the grains' rms speed of rest (energy rule)
  int load_zero_ = 0;      // the loading's kinetic damping, back after a reload
  fabric::RestRule rule_;
  std::unique_ptr<fabric::RestProtocol> protocol_;
  class Fix *lid_ = nullptr;
  class FixQuasiStatic *qs_ = nullptr;
};

}  // namespace LAMMPS_NS

#endif
#endif
