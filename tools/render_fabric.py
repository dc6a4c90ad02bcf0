#!/usr/bin/pvpython
"""Render the primary fabric and the force network of an in.oedometer output
folder with ParaView (the paper's Figs. 9-10), as a PNG.

    pvpython tools/render_fabric.py OUTDIR --out image.png [--step N]
        [--size W H] [--loose-opacity A] [--loose-scale S] [--hide-loose]
        [--tube-radius R] [--min-force F] [--view-dir X Y Z] [--zoom Z]

Loads OUTDIR/grains_N.vtk (dump custom/vtk: id type x y z radius c_pf[1-3]
f_pack) and OUTDIR/contacts_N.vtp (dump local/gran/vtk of compute
pair/gran/local pos id force) of the last step N, or of --step N, and draws
  * the grains as spheres of their true radius (Glyph of ParaView's sphere,
    radius 0.5, scaled by 2 x radius), coloured by class c_pf[2] with a
    legend: primary fabric (opaque) and loose (semi-transparent, optionally
    smaller or hidden) so that the load-carrying skeleton stands out;
  * the contacts as tubes between the two particle centres, radius and colour
    growing with the contact force magnitude |F| (cell array "force", moved to
    the two points of each line; the lines do not share points);
  * the outline of the specimen, a 3/4 view, white background.
If the step has no contacts_N.vtp (in.oedometer writes it only for the final
state) or it has no contact, the grains are drawn alone, with a message.

Headless: Debian 12's ParaView 5.11 has only the X11 OpenGL window (no EGL or
OSMesa), so it needs an X server even with --force-offscreen-rendering
(QT_QPA_PLATFORM=offscreen does not help: pvpython does not render through
Qt). When DISPLAY is unset this script starts its own Xvfb (Debian package
xvfb) with -displayfd, renders into it and stops it at exit, so a plain
    pvpython tools/render_fabric.py OUTDIR --out image.png
works headless. Under xvfb-run, pass -noreset to the server:
    xvfb-run -a -s "-screen 0 1920x1440x24 -noreset" \\
        pvpython --force-offscreen-rendering tools/render_fabric.py ...
(without -noreset about one run in 15 aborts with "bad X server connection":
Xvfb resets when ParaView closes its first connection).
Exit status: 0 on success, 2 on a usage error or missing input.
"""
import argparse
import atexit
import builtins
import glob
import os
import re
import select
import shutil
import subprocess
import sys
import time
import types

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import outputs  # noqa: E402  (the class column of compute primary/fabric, by name)

PROG = "render_fabric.py"
BLACK = [0.0, 0.0, 0.0]


def fail(msg):
    print(PROG + ": error: " + msg, file=sys.stderr)
    sys.exit(2)


def parse_args():
    ap = argparse.ArgumentParser(prog=PROG, description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("outdir", metavar="OUTDIR", help="output folder of input_scripts/in.oedometer")
    ap.add_argument("--out", required=True, metavar="PNG", help="image file to write")
    ap.add_argument("--step", type=int, metavar="N",
                    help="time step of grains_N.vtk / contacts_N.vtp (default: the last)")
    ap.add_argument("--size", type=int, nargs=2, default=[1600, 1200], metavar=("W", "H"),
                    help="image size in pixels (default 1600 1200)")
    ap.add_argument("--loose-opacity", type=float, default=0.12, metavar="A",
                    help="opacity of the loose grains, 0..1 (default 0.12)")
    ap.add_argument("--loose-scale", type=float, default=0.6, metavar="S",
                    help="draw loose grains at S times their radius (default 0.6; 1 is "
                         "true size)")
    ap.add_argument("--hide-loose", action="store_true", help="do not draw the loose grains")
    ap.add_argument("--primary-opacity", type=float, default=0.6, metavar="A",
                    help="opacity of the primary grains, drawn at their true radius "
                         "(default 0.6, so that the force chains inside show; 1: opaque)")
    ap.add_argument("--tube-radius", type=float, metavar="R",
                    help="radius of the tube of the strongest contact in m (default: "
                         "0.35 x the median grain radius; the weakest gets 1/10 of it)")
    ap.add_argument("--min-force", type=float, default=0.0, metavar="F",
                    help="hide contacts with |F| below F times the mean |F| (default 0: "
                         "draw all)")
    ap.add_argument("--view-dir", type=float, nargs=3, default=[1.0, -1.4, 0.9],
                    metavar=("X", "Y", "Z"),
                    help="direction from the specimen to the camera (default 1 -1.4 0.9)")
    ap.add_argument("--zoom", type=float, default=1.0, help="camera zoom factor (default 1)")
    return ap.parse_args()


def numbered(outdir, prefix, ext):
    out = {}
    for f in glob.glob(os.path.join(outdir, prefix + "_*." + ext)):
        m = re.match(re.escape(prefix) + r"_(\d+)\." + ext + "$", os.path.basename(f))
        if m:
            out[int(m.group(1))] = f
    return out


def die_with_parent():
    """In the child: get SIGTERM when pvpython ends, also by a crash (atexit
    does not run after a SIGABRT)."""
    try:
        import ctypes
        import signal
        ctypes.CDLL("libc.so.6", use_errno=True).prctl(1, signal.SIGTERM)  # PR_SET_PDEATHSIG
    except Exception:
        pass


def start_xvfb(args):
    """Debian's ParaView renders only through X11: without DISPLAY, start a
    private Xvfb (it picks a free display and reports it on -displayfd once it
    accepts connections) and point DISPLAY at it; it is stopped at exit.
    -noreset: without it Xvfb resets when ParaView closes its first (test)
    connection, and the next connection can fail during the reset ("bad X
    server connection", SIGABRT), about one run in 15."""
    if os.environ.get("DISPLAY"):
        return
    xvfb = shutil.which("Xvfb")
    if not xvfb:
        fail("no DISPLAY and no Xvfb: Debian's ParaView renders only through X11; "
             "install the package xvfb (apt-get install xvfb) or set DISPLAY")
    w, h = args.size
    rfd, wfd = os.pipe()
    proc = subprocess.Popen(
        [xvfb, "-displayfd", str(wfd), "-nolisten", "tcp", "-noreset",
         "-screen", "0", "%dx%dx24" % (builtins.max(w, 1280) + 64, builtins.max(h, 1024) + 64)],
        pass_fds=(wfd,), stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
        stderr=subprocess.DEVNULL, preexec_fn=die_with_parent)
    os.close(wfd)

    def stop():
        if proc.poll() is None:
            proc.terminate()
            try:
                proc.wait(timeout=10)
            except subprocess.TimeoutExpired:
                proc.kill()
    atexit.register(stop)
    number = b""
    deadline = time.time() + 30.0
    while not number.endswith(b"\n") and time.time() < deadline:
        ready, _, _ = select.select([rfd], [], [], 0.5)
        if ready:
            chunk = os.read(rfd, 64)
            if not chunk:
                break
            number += chunk
    os.close(rfd)
    if not number.strip().isdigit():
        fail("Xvfb did not start (no display number within 30 s)")
    os.environ["DISPLAY"] = ":" + number.strip().decode()


def class_array(names):
    """(point array, component) of the grains' class, the dump column
    outputs.PRIMARY (c_pf[2]: 1 primary, 0 loose), found by its name:
    dump custom/vtk writes c_pf[1] .. c_pf[3] as one array 'c_pf[1-3]' of
    3 components; (None, None) if no array holds it."""
    for name in names:
        k = outputs.vtk_component(name, outputs.PRIMARY)
        if k is not None:
            return name, k
    return None, None


def find_inputs(args):
    """(step, grains_N.vtk, contacts_N.vtp or None) of OUTDIR; fails with a
    usage error if the folder or the step's grains are missing."""
    if not os.path.isdir(args.outdir):
        fail("%s: no such folder" % args.outdir)
    grains = numbered(args.outdir, "grains", "vtk")
    contacts = numbered(args.outdir, "contacts", "vtp")
    if not grains:
        fail("%s: no grains_N.vtk (run input_scripts/in.oedometer with -var out %s)"
             % (args.outdir, args.outdir))
    step = args.step if args.step is not None else max(grains)
    if step not in grains:
        fail("%s: no grains_%d.vtk; steps present: %s"
             % (args.outdir, step, " ".join(str(s) for s in sorted(grains))))
    return step, grains[step], contacts.get(step), contacts


def make_view(ps, args):
    """A render view of the image size, white background, black labels;
    and font(points), font sizes that follow the image size."""
    # (pvpython's programmable filter puts numpy-style max/min/sum into the
    # builtins: this script calls builtins.max explicitly)
    ps._DisableFirstRenderCameraReset()
    view = ps.CreateView("RenderView")
    view.ViewSize = list(args.size)
    view.OrientationAxesVisibility = 1
    if hasattr(view, "UseColorPaletteForBackground"):
        view.UseColorPaletteForBackground = 0
    view.Background = [1.0, 1.0, 1.0]
    if hasattr(view, "Background2"):
        view.Background2 = [1.0, 1.0, 1.0]
    if hasattr(view, "BackgroundColorMode"):
        view.BackgroundColorMode = "Single Color"
    if hasattr(view, "OrientationAxesLabelColor"):
        view.OrientationAxesLabelColor = [0.0, 0.0, 0.0]
    view.EnableRenderOnInteraction = 0
    ps.SetActiveView(view)
    fscale = builtins.min(args.size[0] / 1600.0, args.size[1] / 1200.0) ** 0.5

    def font(points):
        return int(builtins.max(8, builtins.round(points * fscale)))
    return view, font


def read_grains(pv, gfile):
    """The grains' reader, a filter adding the class as the scalar point
    array fabric_class (1 primary, 0 loose), and the fetched data with its
    radius and class arrays."""
    ps, sm, dsa, np = pv.ps, pv.sm, pv.dsa, pv.np
    reader = ps.LegacyVTKReader(FileNames=[gfile])
    reader.UpdatePipeline()
    names = reader.PointData.keys()
    pf, k = class_array(names)
    if "radius" not in names or pf is None:
        fail("%s: needs the point arrays radius and %s (the class of compute "
             "primary/fabric); it has %s" % (gfile, outputs.PRIMARY, ", ".join(names)))
    gdata = dsa.WrapDataObject(sm.Fetch(reader))
    radius = np.asarray(gdata.PointData["radius"])
    cls = np.asarray(gdata.PointData[pf])
    cls = cls[:, k] if cls.ndim > 1 else cls
    # the class as a scalar point array fabric_class: ParaView 5.11's
    # Threshold cannot pick a component of c_pf[1-3] (it would use the first,
    # the loaded-contact count), and the Calculator cannot name it
    classed = ps.ProgrammableFilter(Input=reader)
    classed.CopyArrays = 1
    classed.Script = ("c = inputs[0].PointData[%r]\n"
                      "c = c[:, %d] if c.ndim > 1 else c\n"
                      "output.PointData.append((c > 0.5).astype('float64'), "
                      "'fabric_class')\n" % (pf, k))
    classed.UpdatePipeline()
    return classed, gdata, radius, cls


def draw_grains(pv, view, font, args, classed, n_prim, n_all):
    """The primary and the loose grains as spheres coloured by class, with
    the class legend."""
    ps = pv.ps
    lut = ps.GetColorTransferFunction("fabric_class")
    lut.InterpretValuesAsCategories = 1
    lut.Annotations = ["1", "primary fabric: %d grains" % n_prim,
                       "0", "loose: %d grains%s" % (n_all - n_prim,
                                                    " (hidden)" if args.hide_loose else "")]
    # colours in the order of the annotations: primary slate grey, loose sand
    # (the tubes take the force colour map)
    lut.IndexedColors = [0.42, 0.47, 0.56, 0.90, 0.76, 0.50]
    if n_prim:
        grain_set(ps, view, lut, classed, 1, 1.0, args.primary_opacity, 20)
    if not args.hide_loose and n_prim < n_all:
        grain_set(ps, view, lut, classed, 0, args.loose_scale, args.loose_opacity, 12)
    bar = ps.GetScalarBar(lut, view)
    bar.Title = "grain class"
    bar.ComponentTitle = ""
    bar.HorizontalTitle = 1
    if hasattr(bar, "TextPosition"):
        bar.TextPosition = "Ticks left/bottom, annotations right/top"
    bar.TitleColor = BLACK
    bar.LabelColor = BLACK
    bar.TitleFontSize = font(18)
    bar.LabelFontSize = font(16)
    bar.WindowLocation = "Any Location"
    bar.Position = [0.09, 0.78]
    bar.ScalarBarLength = 0.12


def grain_set(ps, view, lut, classed, value, scale, opacity, resolution):
    """The grains of class `value` as spheres of `scale` x their radius."""
    th = ps.Threshold(Input=classed)
    th.Scalars = ["POINTS", "fabric_class"]
    lo, hi = value - 0.5, value + 0.5
    if hasattr(th, "LowerThreshold"):
        th.LowerThreshold, th.UpperThreshold = lo, hi
        th.ThresholdMethod = "Between"
    else:
        th.ThresholdRange = [lo, hi]
    gl = ps.Glyph(Input=th, GlyphType="Sphere")
    gl.OrientationArray = ["POINTS", "No orientation array"]
    gl.ScaleArray = ["POINTS", "radius"]
    gl.ScaleFactor = 2.0 * scale        # the glyph sphere has radius 0.5
    gl.GlyphMode = "All Points"
    gl.GlyphType.ThetaResolution = resolution
    gl.GlyphType.PhiResolution = builtins.max(6, (2 * resolution) // 3)
    rep = ps.Show(gl, view)
    ps.ColorBy(rep, ("POINTS", "fabric_class"))
    rep.LookupTable = lut
    rep.Opacity = opacity
    rep.Specular = 0.2
    rep.SetScalarBarVisibility(view, True)
    return rep


def draw_outline(pv, view, gdata, radius):
    """The specimen's outline, grain centres +- radius (the container's
    walls); returns its (lo, hi) corners."""
    ps, np = pv.ps, pv.np
    pts = np.asarray(gdata.Points).reshape(-1, 3)
    if len(radius):
        lo = (pts - radius[:, None]).min(axis=0)
        hi = (pts + radius[:, None]).max(axis=0)
    else:
        lo, hi = np.zeros(3), np.ones(3)
    box = ps.Box(XLength=float(hi[0] - lo[0]), YLength=float(hi[1] - lo[1]),
                 ZLength=float(hi[2] - lo[2]), Center=[float(v) for v in 0.5 * (lo + hi)])
    outline = ps.Outline(Input=box)
    orep = ps.Show(outline, view)
    orep.ColorArrayName = ["POINTS", ""]
    orep.AmbientColor = orep.DiffuseColor = [0.35, 0.35, 0.35]
    orep.LineWidth = 1.5
    return lo, hi


def read_contacts(pv, cfile):
    """(reader, number of contacts, their |F|) of contacts_N.vtp; no
    contact if there is no file or it has none."""
    if not cfile:
        return None, 0, None
    ps, sm, dsa, np = pv.ps, pv.sm, pv.dsa, pv.np
    creader = ps.XMLPolyDataReader(FileName=[cfile])
    creader.UpdatePipeline()
    cdata = dsa.WrapDataObject(sm.Fetch(creader))
    if cdata.GetNumberOfCells() == 0 or "force" not in creader.CellData.keys():
        print("%s: %s has no contact: drawing the grains only" % (PROG, cfile))
        return creader, 0, None
    fvec = np.asarray(cdata.CellData["force"]).reshape(-1, 3)
    return creader, cdata.GetNumberOfCells(), np.linalg.norm(fvec, axis=1)


def draw_contacts(pv, view, font, args, creader, fmag, r_med):
    """The contacts as tubes whose radius and colour grow with |F|, with the
    force legend; returns the largest |F|."""
    ps = pv.ps
    fmax, fmean = float(fmag.max()), float(fmag.mean())
    c2p = ps.CellDatatoPointData(Input=creader)
    calc = ps.Calculator(Input=c2p)
    calc.AttributeType = "Point Data"
    calc.ResultArrayName = "force_magnitude"
    calc.Function = "mag(force)"
    src = calc
    if args.min_force > 0:
        thf = ps.Threshold(Input=calc)
        thf.Scalars = ["POINTS", "force_magnitude"]
        if hasattr(thf, "LowerThreshold"):
            thf.LowerThreshold, thf.UpperThreshold = args.min_force * fmean, 1e300
            thf.ThresholdMethod = "Between"
        else:
            thf.ThresholdRange = [args.min_force * fmean, 1e300]
        src = ps.ExtractSurface(Input=thf)
    tube = ps.Tube(Input=src)
    rmax = args.tube_radius if args.tube_radius else 0.35 * r_med
    tube.Scalars = ["POINTS", "force_magnitude"]
    tube.VaryRadius = "By Scalar"
    tube.Radius = rmax / 10.0                   # the weakest contact
    tube.RadiusFactor = 10.0                    # the strongest: 10 x the weakest
    tube.NumberofSides = 12
    tube.Capping = 1
    trep = ps.Show(tube, view)
    ps.ColorBy(trep, ("POINTS", "force_magnitude"))
    force_legend(ps, view, font, trep, fmax)
    return fmax


def force_legend(ps, view, font, trep, fmax):
    """The force colour map (Turbo, else Jet, else a rainbow) and its bar."""
    flut = ps.GetColorTransferFunction("force_magnitude")
    for preset in ("Turbo", "Jet", "Rainbow Uniform"):
        try:
            if flut.ApplyPreset(preset, True):
                break
        except Exception:
            pass
    flut.RescaleTransferFunction(0.0, fmax if fmax > 0 else 1.0)
    if hasattr(flut, "AutomaticRescaleRangeMode"):
        flut.AutomaticRescaleRangeMode = "Never"
    trep.SetScalarBarVisibility(view, True)
    fbar = ps.GetScalarBar(flut, view)
    fbar.Title = "contact force (N)"
    fbar.ComponentTitle = ""
    fbar.TitleColor = BLACK
    fbar.LabelColor = BLACK
    fbar.TitleFontSize = font(18)
    fbar.LabelFontSize = font(16)
    fbar.RangeLabelFormat = "%-#.2g"
    fbar.WindowLocation = "Any Location"
    fbar.Position = [0.88, 0.10]
    fbar.ScalarBarLength = 0.45


def place_camera(pv, view, args, lo, hi):
    """A perspective view of the specimen from --view-dir, z up."""
    np = pv.np
    centre = [float(v) for v in 0.5 * (lo + hi)]
    diag = builtins.max(float(np.linalg.norm(hi - lo)), 1e-12)
    d = np.asarray(args.view_dir, float)
    d = d / np.linalg.norm(d)
    cam = view.GetActiveCamera()
    cam.SetFocalPoint(*centre)
    cam.SetPosition(*(np.asarray(centre) + 2.5 * diag * d))
    cam.SetViewUp(0.0, 0.0, 1.0)
    view.CameraParallelProjection = 0
    view.ResetCamera(False)
    cam.Zoom(args.zoom)


def main():
    args = parse_args()
    step, gfile, cfile, contacts = find_inputs(args)
    start_xvfb(args)
    if cfile is None:
        print("%s: no contacts_%d.vtp (contacts at steps: %s): drawing the grains only"
              % (PROG, step, " ".join(str(s) for s in sorted(contacts)) or "none"))

    import paraview.simple as ps
    from paraview import servermanager as sm
    from vtk.numpy_interface import dataset_adapter as dsa
    import numpy as np
    pv = types.SimpleNamespace(ps=ps, sm=sm, dsa=dsa, np=np)

    view, font = make_view(ps, args)
    classed, gdata, radius, cls = read_grains(pv, gfile)
    n_prim, n_all = int(np.sum(cls > 0.5)), len(cls)
    r_med = float(np.median(radius)) if n_all else 1.0
    draw_grains(pv, view, font, args, classed, n_prim, n_all)
    lo, hi = draw_outline(pv, view, gdata, radius)
    creader, n_contacts, fmag = read_contacts(pv, cfile)
    fmax = draw_contacts(pv, view, font, args, creader, fmag, r_med) if n_contacts else 0.0

    title = ps.Text(Text="step %d: %d grains, %d primary (%.1f %% by number), %d contacts%s"
                    % (step, n_all, n_prim, 100.0 * n_prim / builtins.max(n_all, 1), n_contacts,
                       ", largest force %.3g N" % fmax if n_contacts else ""))
    tr = ps.Show(title, view)
    tr.Color = BLACK
    tr.FontSize = font(20)
    tr.WindowLocation = "Upper Center"
    place_camera(pv, view, args, lo, hi)

    out = os.path.abspath(args.out)
    os.makedirs(os.path.dirname(out), exist_ok=True)
    ps.Render(view)
    ps.SaveScreenshot(out, view, ImageResolution=list(args.size), TransparentBackground=0)
    print(out)


if __name__ == "__main__":
    main()
