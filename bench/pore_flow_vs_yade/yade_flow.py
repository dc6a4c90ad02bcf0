# YADE's FlowEngine (Debian's yade 2023.02a) on a packing exported by
# pore_flow_bench: the same box as six walls (aabbWalls, ids 0-5, their
# positions rather than the spheres' extremes), the inflow pressure on z lo,
# the outflow pressure on z hi, the side walls impermeable, every other
# setting FlowEngine's default; one step with the grains held fixed.
#   yade -n -x yade_flow.py SPHERES p_in p_out viscosity PREFIX
# prints the flows and the permeability, writes PREFIX_cells.txt (centre,
# pressure) and PREFIX_forces.txt (per sphere). CLAMP=0 in the environment
# turns FlowEngine's clampKValues off.
import os
import sys
from yade import utils
args = sys.argv[1:]
path, p_in, p_out, mu, prefix = args[0], float(args[1]), float(args[2]), float(args[3]), args[4]
lines = open(path).read().split('\n')
box = [float(v) for v in lines[0].split()]
lo, hi = Vector3(*box[:3]), Vector3(*box[3:])
walls = utils.aabbWalls([lo, hi], thickness=0)
for w in walls: O.bodies.append(w)
for l in lines[1:]:
    if l.strip():
        x, y, z, r = [float(v) for v in l.split()]
        O.bodies.append(sphere((x, y, z), r))
flow = FlowEngine(dead=False)
flow.boundaryUseMaxMin = [False] * 6
flow.bndCondIsPressure = [False, False, False, False, True, True]
flow.bndCondValue = [0, 0, 0, 0, p_in, p_out]
flow.viscosity = mu
flow.clampKValues = os.environ.get("CLAMP", "1") == "1"
# No collider and no contact law: the grains are fixed and the forces
# written are the fluid's alone.
O.engines = [ForceResetter(), flow, NewtonIntegrator(damping=0)]
O.dt = 1e-9
for b in O.bodies: b.state.blockedDOFs = 'xyzXYZ'
O.run(1, True)
qin, qout = flow.getBoundaryFlux(4), flow.getBoundaryFlux(5)
A = (hi[0] - lo[0]) * (hi[1] - lo[1]); L = hi[2] - lo[2]
print('YADE inflow %.9e outflow %.9e permeability %.9e' % (qin, qout, abs(qout) * mu * L / (A * (p_in - p_out))))
with open(prefix + '_cells.txt', 'w') as f:
    for i in range(flow.nCells()):
        c = flow.getCellCenter(i)
        f.write('%.12g %.12g %.12g %.12g\n' % (c[0], c[1], c[2], flow.getCellPressure(i)))
with open(prefix + '_forces.txt', 'w') as f:
    for b in O.bodies:
        if isinstance(b.shape, Sphere):
            F = O.forces.f(b.id)
            f.write('%.12g %.12g %.12g\n' % (F[0], F[1], F[2]))
