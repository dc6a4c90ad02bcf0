// Pore-scale flow through a fixed packing of spheres: the pore finite-volume
// method of Chareyre, Scholtès & Darve (2012), "Pore-scale modeling of
// viscous flow and induced forces in dense sphere packings", Transport in
// Porous Media 94:595-615, the method of YADE's FlowEngine.
//
// Plain C++ with Eigen, no LIGGGHTS include. The pores are the cells of the
// regular triangulation (core/regular_triangulation.h, the one the
// constrictions use) with the box's walls as six more vertices, so that the
// cells fill the box; each pore's centre is its orthocentre (the power
// diagram's vertex). The throats are the faces between two cells. A face with
// a wall vertex is the polygon that the face's spheres span down to that wall
// (the sphere centres and their projections on it), as FlowEngine builds it.
//
// Per throat, Chareyre et al.'s conductance
//     g = A_f R_h^2 / (2 mu L)
// where A_f is the face's fluid area (the polygon minus the spheres' sections
// in it), L the distance between the two pore centres (at least 0.1 R_h, as
// FlowEngine's distance correction floors it) and R_h the hydraulic
// radius of the throat's region Omega: the bipyramid of the face polygon with
// the two pore centres as apexes, R_h = (fluid volume in Omega) / (sphere
// surface in Omega). For a circular tube (A = pi a^2, R_h = a / 2) it is
// Poiseuille's pi a^4 / (8 mu L). FlowEngine writes the same conductance as
// A_f (2 R_h)^2 / (8 mu L) (permeabilityFactor 1).
//
// Boundary conditions: the pores with a vertex on the wall z = lo hold the
// inflow pressure, those on z = hi the outflow pressure (FlowEngine imposes
// a wall's pressure on the cells incident to it the same way); the side
// walls are impermeable and slip (not wetted, as FlowEngine's default
// slipBoundary). The other pores' pressures solve the mass balance
// sum_j g_ij (p_i - p_j) = 0 with Eigen's conjugate gradients.
//
// The fluid's force on each sphere (Chareyre et al.), per face
// between pores a and b, with n the face's unit normal from a to b:
//   pressure  (p_a - p_b) s_k n, s_k the sphere's section in the face: the
//             pressure of each pore on the sphere's surface inside it, summed
//             face by face (the surface inside a cell closes with its
//             sections on the cell's faces);
//   viscous   (p_a - p_b) A_f n, the fluid's momentum balance in Omega,
//             shared among the face's spheres in proportion to their wetted
//             surface in Omega.
// Summed over the grains they equal the pressure drop times the cross-section
// along z (the walls take the rest), which the tests check: the normal n,
// not the line between the pore centres (parallel to it in a power diagram
// but for its sign where a cell's orthocentre lies outside the cell), is
// what makes the sum exact.
//
// Where we differ from FlowEngine (measured in bench/pore_flow_vs_yade):
// cells whose orthocentres coincide are one pore (FlowEngine keeps them
// apart, joined by a throat of zero length that it gives an "infinite"
// conductance); no conductance is clamped (FlowEngine's clampKValues bounds
// them by a multiple of a quantity one length unit short of a conductance,
// so its permeability depends on the unit of length: 2.26 times ours at
// millimetre grains); the solid angles use atan2 (FlowEngine's 2 atan loses
// angles above pi sr); the fluid area has no correction for a section that
// crosses the face's opposite edge (FlowEngine's S0), it is floored at zero.
#ifndef FABRIC_PORE_FLOW_H
#define FABRIC_PORE_FLOW_H

#include <array>
#include <vector>

#include "box.h"
#include "geometry.h"

namespace fabric {

// Water at 20 C.
constexpr double kWaterViscosity = 1.0e-3;  // Pa s

struct PoreFlowOptions {
  Box box;                            // the container: the walls
  double viscosity = kWaterViscosity;  // Pa s
  double inflow_pressure = 1.0;       // Pa, on the face z = box.lo.z
  double outflow_pressure = 0.0;      // Pa, on the face z = box.hi.z
  // Conjugate gradients stop at this residual relative to the right-hand
  // side; inflow and outflow then agree to about this share.
  double tolerance = 1e-12;
};

// How a cell takes part in the flow.
enum class PoreKind : char {
  unknown,  // its pressure is solved for
  inflow,   // a vertex on z = lo: the inflow pressure
  outflow,  // a vertex on z = hi: the outflow pressure
  solid     // not a pore of the box (two opposite walls): no fluid
};

struct PoreThroat {
  long cell_a, cell_b;  // the face's two cells (of two different pores)
  double conductance;   // m^3 / (Pa s)
  double flux;          // m^3 / s, from a to b
};

// Per cell (the triangulation's, in its order): a pore is one cell, or
// several whose orthocentres coincide (within 1e-6 of the face's largest
// radius, as the constrictions merge them: a lattice's octahedron, or the
// packer's local lattices of equal spheres, split into tetrahedra with no
// throat length between them), named by its first cell.
struct PoreFlow {
  std::vector<double> pressure;   // per cell, Pa: its pore's
  std::vector<Vec3> centre;       // per cell: its orthocentre
  std::vector<PoreKind> kind;     // per cell: its pore's
  std::vector<long> pore;         // per cell: its pore's first cell
  std::vector<PoreThroat> throats;
  std::vector<Vec3> force;          // per sphere, N: pressure + viscous
  std::vector<Vec3> viscous_force;  // per sphere, N: the viscous part
  // per sphere, Pa: the pressure of the pores around it, the mean of each
  // face's two pores (one, against a wall) weighted by the sphere's section
  // in the face: the pressure field as the grains see it, for dumps
  std::vector<double> grain_pressure;
  double inflow = 0.0, outflow = 0.0;  // m^3 / s
  double cross_section = 0.0;          // m^2, of the box across z
  double length = 0.0;                 // m, the box's height
  // Darcy: Q mu L / (A dp), Q the outflow.
  double permeability = 0.0;  // m^2
  long pores = 0;             // pores (not solid)
  long merged = 0;            // cells joined to a pore's first cell
  // Unknown pores that no throat connects to an inflow or outflow pore:
  // they hold the mean of the two pressures and carry no flow.
  long isolated = 0;
  int iterations = 0;
  double solver_error = 0.0;  // relative residual reached
};

// Throws std::invalid_argument, naming the value, for fewer than 4 spheres,
// a non-finite centre or a radius not positive and finite, a centre outside
// the box, an empty box, a viscosity not positive and finite, or a pressure
// drop (inflow - outflow) that is not positive.
PoreFlow pore_flow(const std::vector<Sphere>& spheres,
                   const PoreFlowOptions& options);

// The geometry of one throat: a planar convex face polygon whose corners are
// sphere centres (radius > 0) or points on a wall (radius 0), between the
// pore centres a and b; `behind_a` is any point on a's side of the face.
struct ThroatGeometry {
  Vec3 normal = Vec3::Zero();  // unit, from a's side to b's
  double area = 0.0;           // of the polygon
  double fluid_area = 0.0;     // the polygon minus the spheres' sections
  double fluid_volume = 0.0;   // in the bipyramid Omega
  double wetted_surface = 0.0;  // sphere surface in Omega
  double length = 0.0;          // |a - b|
  std::array<double, 4> section{};  // per corner: the sphere's section
  std::array<double, 4> wetted{};   // per corner: its surface in Omega
  double hydraulic_radius() const {
    return wetted_surface > 0.0 ? fluid_volume / wetted_surface : 0.0;
  }
};
ThroatGeometry throat_geometry(const std::vector<Vec3>& corner,
                               const std::vector<double>& radius,
                               const Vec3& a, const Vec3& b,
                               const Vec3& behind_a);

// Chareyre et al.'s conductance, g = A_f R_h^2 / (2 mu L).
double throat_conductance(double fluid_area, double hydraulic_radius,
                          double length, double viscosity);

}  // namespace fabric

#endif
