#include "command_psd_info.h"

#include <cstdio>
#include <cstring>
#include <exception>
#include <string>
#include <vector>

#include "comm.h"
#include "error.h"
#include "input.h"
#include "psd.h"
#include "style_args.h"

using namespace LAMMPS_NS;

void CommandPsdInfo::command(int narg, char **arg) {
  const std::string usage = "psd_info FILE [intervals N]";
  if (narg != 1 && narg != 3)
    error->all(FLERR, ("psd_info: expected '" + usage + "'").c_str());
  const std::string file = arg[0];  // input->one() below reuses arg
  int n = 20;
  if (narg == 3) {
    const StyleArgs args(error, "psd_info", narg - 1, arg + 1, {"intervals"});
    if (strcmp(arg[1], "intervals") != 0)
      args.fail("unknown keyword '" + std::string(arg[1]) + "': expected '" +
                usage + "'");
    const long v = args.integer(0, "an integer in 1..100");
    args.require(v >= 1 && v <= 100, 0, "must be an integer in 1..100");
    n = static_cast<int>(v);
  }
  std::vector<fabric::SizeInterval> intervals;
  double d10 = 0, d60 = 0;
  try {
    const auto psd = fabric::ParticleSizeDistribution::read(file);
    intervals = psd.equal_mass_intervals(n);
    d10 = psd.d10();
    d60 = psd.d60();
  } catch (const std::exception &e) {
    error->all(FLERR, (std::string("psd_info: ") + e.what()).c_str());
  }
  const double values[] = {intervals.back().d_mean, intervals.front().d_mean,
                           d10, d60, d60 / d10};
  const char *names[] = {"psd_dN", "psd_d1", "psd_d10", "psd_d60", "psd_Cu"};
  for (int k = 0; k < 5; ++k) {
    char line[128];
    snprintf(line, sizeof line, "variable %s equal %.17g", names[k], values[k]);
    input->one(line);
  }
  if (comm->me == 0) {
    char msg[512];
    snprintf(msg, sizeof msg,
             "psd_info %s: d10 = %g, d60 = %g, Cu = %g; %d equal-mass "
             "intervals from d_1 = %g to d_N = %g (psd_d10 psd_d60 psd_Cu "
             "psd_d1 psd_dN)\n",
             file.c_str(), d10, d60, d60 / d10, n, values[1], values[0]);
    if (screen) fputs(msg, screen);
    if (logfile) fputs(msg, logfile);
  }
}
