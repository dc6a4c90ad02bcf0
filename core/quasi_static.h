// The quasi-static protocol's mechanics, with no LIGGGHTS include: Cundall's
// local non-viscous damping and the unbalanced-force ratio that calls rest
// by force balance (fix quasi/static is their LIGGGHTS adapter).
//
// Local damping (Cundall 1987; PFC's default 0.7, YADE's
// NewtonIntegrator(damping=0.2)): each component of a grain's force, and of
// its torque, is reduced by alpha times its magnitude against the sign of
// the matching velocity (angular velocity) component,
//   F_k <- F_k - alpha |F_k| sign(v_k).
// It vanishes with the force, so a grain in equilibrium feels none and a
// steady motion under a balanced load is not resisted: unlike a viscous drag
// it does not move where the packing comes to rest, only how fast.
//
// The unbalanced-force ratio (YADE's unbalancedForce, PFC's mean force
// ratio): the mean magnitude of the resultant force on the grains that
// carry load over the mean magnitude of a contact force. 0 at static
// equilibrium; a packing still rearranging reads 1e-2 or more.
#ifndef FABRIC_QUASI_STATIC_H
#define FABRIC_QUASI_STATIC_H

#include <array>
#include <vector>

namespace fabric {

// The damping coefficient alpha must lie in [0, 1): 1 would cancel every
// force that pushes a grain along its motion.
bool valid_local_damping(double alpha);

// One component: the force after local damping.
double local_damping(double force, double velocity, double alpha);

// The three components of a force (torque) f against the velocity (angular
// velocity) v, in place.
void damp_locally(double *f, const double *v, double alpha);

// Sums for the unbalanced-force ratio on one rank; ranks add them up.
struct ForceBalance {
  double resultant_sum = 0.0;  // sum of |F| over the grains counted
  double grains = 0.0;         // grains counted (with a loaded contact)
  double contact_sum = 0.0;    // sum of |contact force| over the contacts
  double contacts = 0.0;       // contacts counted

  void add_grain(const double *resultant);
  void add_contact(double magnitude);
  // mean |F| / mean |contact force|; infinity when there is no contact
  // force (an unloaded specimen is not at rest by this measure).
  double ratio() const;
  // for MPI: the four sums as one array, and back
  std::array<double, 4> sums() const;
  static ForceBalance from_sums(const std::array<double, 4> &s);
};

// A hand-built configuration's balance: grains, contacts between them
// (force on grain i, the opposite on j; j < 0 for a wall) and external
// forces; each grain's resultant is the sum of what acts on it. For tests
// and for checking the adapter against an independent recount.
struct PairForce {
  int i, j;
  std::array<double, 3> force_on_i;
};
ForceBalance balance_of(int grains, const std::vector<PairForce> &contacts,
                        const std::vector<std::array<double, 3>> &external);

}  // namespace fabric

#endif
