#!/usr/bin/env python3
"""Plot the deformed mid-plane slice of a 3D LtN elasticity run with a crack
(e.g. parameter_files/lps_bar_3d_tensile_crack.prm) from its VTU output.

usage: python3 scripts/plot_cracked_bar.py OUTPUT_DIR PNG [--level 0]
                                           [--scale S] [--z Z]

The slice is the layer of particles nearest to the plane z = Z (default: the
body's mid-plane) and the local mesh cut by the same plane. Positions are
warped by S times the displacement. Panels: (a) the whole bar, particles and
mesh cells coloured by region; zooms on the particle block: (b) regions,
(c) axial displacement u_x, (d) broken bond fraction. The cracks, read from
OUTPUT_DIR/used_parameters.prm, are drawn as dashed black lines in the middle
of the opening they cause.

Needs Debian's python3-vtk9, python3-numpy and python3-matplotlib.
"""
import argparse
import json
import os
import sys

import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.collections import EllipseCollection, PolyCollection  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402
from matplotlib.patches import Patch  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from run_output import level_file, run_name  # noqa: E402
from vtu_fields import read_grid, read_vtu  # noqa: E402

# Region tags (doc/discretization.md, 'Geometry and region tags'), coloured
# as in plot_fields_2d.py (tab10).
REGIONS = {0: "nonlocal", 1: "physical collar", 2: "control collar",
           3: "overlap", 4: "local"}
COLOURS = {k: plt.get_cmap("tab10")(k) for k in REGIONS}


def parse_args():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("directory", help="the run's output directory")
    parser.add_argument("png", help="the picture to write")
    parser.add_argument("--level", type=int, default=0)
    parser.add_argument("--scale", type=float, default=200.0,
                        help="warp factor of the displacement (default 200)")
    parser.add_argument("--z", type=float, default=None,
                        help="slice plane (default: the body's mid-plane)")
    return parser.parse_args()


def slice_grid(grid, z):
    """Cut the hexahedral mesh grid by the plane z. Return the cut's points,
    its polygons (lists of point indices) and its interpolated point
    fields."""
    bounds = np.array(grid.GetBounds()).reshape(3, 2)
    # A plane through a layer of mesh faces cuts degenerately; the
    # displacement is continuous, so move it off by a negligible amount.
    nodes_z = np.unique(np.round(vtk_to_numpy(grid.GetPoints().GetData())[:, 2],
                                 12))
    if np.min(np.abs(nodes_z - z)) < 1e-9 * (bounds[2, 1] - bounds[2, 0]):
        z += 1e-6 * (bounds[2, 1] - bounds[2, 0])
    plane = vtk.vtkPlane()
    plane.SetOrigin(0, 0, z)
    plane.SetNormal(0, 0, 1)
    cutter = vtk.vtkCutter()
    cutter.SetCutFunction(plane)
    cutter.SetInputData(grid)
    cutter.GenerateTrianglesOff()  # keep the hexahedra's cuts as quads
    cutter.Update()
    cut = cutter.GetOutput()
    points = vtk_to_numpy(cut.GetPoints().GetData())
    data = cut.GetPointData()
    fields = {data.GetArrayName(i): vtk_to_numpy(data.GetArray(i))
              for i in range(data.GetNumberOfArrays())}
    polygons = []
    ids = vtk.vtkIdList()
    cells = cut.GetPolys()
    cells.InitTraversal()
    while cells.GetNextCell(ids):
        polygons.append([ids.GetId(i) for i in range(ids.GetNumberOfIds())])
    return points, polygons, fields


def read_cracks(directory):
    """The 3D cracks of used_parameters.prm: a list of (3, 3) arrays holding
    the corners c0, c1, c2 of each parallelogram."""
    path = os.path.join(directory, "used_parameters.prm")
    if not os.path.exists(path):
        return []
    section = None
    for line in open(path):
        words = line.split("#")[0].split()
        if words[:1] == ["subsection"]:
            section = " ".join(words[1:])
        elif words[:1] == ["end"]:
            section = None
        elif section == "Cracks" and words[:2] == ["set", "Corners"]:
            value = line.split("#")[0].split("=", 1)[1]
            cracks = []
            for text in value.split(";"):
                numbers = [float(v) for v in text.split(",") if v.strip()]
                if len(numbers) == 9:
                    cracks.append(np.array(numbers).reshape(3, 3))
            return cracks
    return []


def crack_segment(corners, z):
    """The segment where the plane z cuts the parallelogram, or None."""
    c0, c1, c2 = corners
    quad = [c0, c1, c1 + c2 - c0, c2]
    hits = []
    for a, b in zip(quad, quad[1:] + quad[:1]):
        if (a[2] - z) * (b[2] - z) <= 0 and a[2] != b[2]:
            hits.append(a + (z - a[2]) / (b[2] - a[2]) * (b - a))
    if len(hits) < 2:
        return None
    hits = np.array(hits)
    # Two hits, or more where the plane runs through a corner: keep the
    # farthest pair.
    distance = np.linalg.norm(hits[:, None] - hits[None], axis=2)
    i, j = np.unravel_index(np.argmax(distance), distance.shape)
    return hits[[i, j]] if distance[i, j] > 0 else None


def main():
    args = parse_args()
    level = f"level-{args.level:02d}"
    for kind in ("particles", "local_mesh"):
        path = level_file(args.directory, kind, args.level)
        if not os.path.exists(path):
            sys.exit(f"error: {path} does not exist (a 3D run with "
                     f"'Write VTU = true' and at least {args.level + 1} "
                     "levels writes it)")
    xp, p = read_vtu(level_file(args.directory, "particles", args.level))
    mesh = read_grid(level_file(args.directory, "local_mesh", args.level))
    bounds = np.array(mesh.GetBounds()).reshape(3, 2)
    for key, value in p.items():
        if not np.all(np.isfinite(value)):
            print(f"warning: particle field {key} has "
                  f"{np.count_nonzero(~np.isfinite(value))} non-finite "
                  "values", file=sys.stderr)
    z_plane = args.z if args.z is not None else bounds[2].mean()
    s = args.scale

    # The particle layer nearest to the plane: particles sit at cell
    # centres of the lattice, so with an even number of layers there is none
    # on the mid-plane itself, and |z - z_plane| < h_p / 2 would select
    # nothing. Take the nearest layer and say so in the title.
    layers = np.unique(np.round(xp[:, 2], 9))
    z_layer = layers[np.argmin(np.abs(layers - z_plane))]
    h_p = np.min(np.diff(layers)) if len(layers) > 1 else 1.0
    mesh_points, mesh_polygons, m = slice_grid(mesh, z_layer)
    for key, value in m.items():
        if not np.all(np.isfinite(value)):
            print(f"warning: mesh field {key} has "
                  f"{np.count_nonzero(~np.isfinite(value))} non-finite "
                  "values in the slice", file=sys.stderr)
    in_layer = np.abs(xp[:, 2] - z_layer) < 1e-6 * h_p
    x = xp[in_layer]
    u = p["displacement"][in_layer]
    region = np.rint(p["region"][in_layer]).astype(int)
    broken = p["broken_bond_fraction"][in_layer]
    warped = x[:, :2] + s * u[:, :2]

    mesh_warped = mesh_points[:, :2] + s * m["displacement"][:, :2]
    mesh_region = m["region"]
    polygons = [mesh_warped[ids] for ids in mesh_polygons]
    # A cell is drawn as overlap when all its cut vertices are tagged overlap.
    polygon_overlap = np.array([np.max(mesh_region[ids]) < 3.5
                                for ids in mesh_polygons])

    # The cracks in this slice, warped by the mean displacement of the
    # particles within h_p of each point (the particles on both sides).
    crack_lines = []
    for corners in read_cracks(args.directory):
        segment = crack_segment(corners, z_layer)
        if segment is None:
            continue
        t = np.linspace(0, 1, max(2, int(np.ceil(
            np.linalg.norm(segment[1] - segment[0]) / (h_p / 2))) + 1))
        line = segment[0] + t[:, None] * (segment[1] - segment[0])
        shifted = []
        for point in line:
            near = np.linalg.norm(x[:, :2] - point[:2], axis=1) <= h_p * 1.0001
            du = u[near, :2].mean(axis=0) if near.any() else 0.0
            shifted.append(point[:2] + s * du)
        crack_lines.append(np.array(shifted))

    # The opening seen in the slice: the jump of u along the crack normal
    # between the two particles on either side of it, h_p apart (what
    # summary.json's crack_openings report; it includes the elastic
    # stretch over one spacing).
    openings = []
    for corners in read_cracks(args.directory):
        c0, c1, c2 = corners
        normal = np.cross(c1 - c0, c2 - c0)
        normal /= np.linalg.norm(normal)
        e1, e2 = c1 - c0, c2 - c0
        for i in range(len(x)):
            d = np.dot(x[i] - c0, normal)
            if abs(d - h_p / 2) > 1e-6 * h_p:
                continue
            foot = x[i] - d * normal - c0
            a = np.dot(foot, e1) / np.dot(e1, e1)
            b = np.dot(foot, e2) / np.dot(e2, e2)
            if not (0 <= a <= 1 and 0 <= b <= 1):
                continue
            partner = np.linalg.norm(x - (x[i] - h_p * normal), axis=1) < \
                1e-6 * h_p
            if partner.any():
                openings.append(np.dot(u[i] - u[partner][0], normal))
    max_opening = max(openings) if openings else float("nan")

    summary_opening = None
    name = run_name(args.directory)
    summary = os.path.join(args.directory, "summary.json")
    if os.path.exists(summary):
        summary = json.load(open(summary))
        name = summary.get("scene", name)
        cracks = (summary.get("mechanics") or {}).get("crack_openings") or []
        if cracks:
            summary_opening = max(c["max_opening"] for c in cracks)

    # Layout: the whole bar on top, three zooms on the particle block below.
    figure = plt.figure(figsize=(10.7, 7.6))
    grid = figure.add_gridspec(2, 3, height_ratios=[2.95, 2.75],
                               hspace=0.27, wspace=0.1,
                               left=0.055, right=0.985, top=0.865,
                               bottom=0.145)
    whole = figure.add_subplot(grid[0, :])
    zooms = [figure.add_subplot(grid[1, k]) for k in range(3)]
    # Colour bars under (c) and (d), as wide as the (equal-aspect) axes.
    colourbars = [axis.inset_axes([0, -0.25, 1, 0.045]) for axis in zooms[1:]]

    def draw_mesh(axis, facecolors, linewidth=0.5):
        axis.add_collection(PolyCollection(
            polygons, facecolors=facecolors, edgecolors="0.55",
            linewidths=linewidth, zorder=1))

    def draw_particles(axis, colours=None, values=None, cmap=None, norm=None):
        # Discs of diameter 0.72 h_p in data units, above the mesh.
        diameter = np.full(len(x), 0.72 * h_p)
        dots = EllipseCollection(
            diameter, diameter, np.zeros(len(x)), units="xy", offsets=warped,
            offset_transform=axis.transData, edgecolors="0.2",
            linewidths=0.3, zorder=2)
        if values is not None:
            dots.set_array(values)
            dots.set_cmap(cmap)
            dots.set_norm(norm)
        else:
            dots.set_facecolor(colours)
        axis.add_collection(dots)
        return dots

    def draw_cracks(axis):
        for line in crack_lines:
            axis.plot(line[:, 0], line[:, 1], color="k", lw=1.6,
                      ls=(0, (3, 1.5)), zorder=3, solid_capstyle="butt")

    region_colours = [COLOURS[k] for k in region]
    overlap_tint = np.array(matplotlib.colors.to_rgba(COLOURS[3])) * \
        [1, 1, 1, 0.28]
    local_tint = np.array(matplotlib.colors.to_rgba(COLOURS[4])) * \
        [1, 1, 1, 0.16]
    mesh_tints = [overlap_tint if o else local_tint for o in polygon_overlap]

    # (a) the whole bar.
    draw_mesh(whole, mesh_tints)
    draw_particles(whole, colours=region_colours)
    draw_cracks(whole)
    reference = np.array([[bounds[0, 0], bounds[1, 0]],
                          [bounds[0, 1], bounds[1, 0]],
                          [bounds[0, 1], bounds[1, 1]],
                          [bounds[0, 0], bounds[1, 1]],
                          [bounds[0, 0], bounds[1, 0]]])
    whole.plot(reference[:, 0], reference[:, 1], color="0.4", lw=0.8,
               ls=":", zorder=0)
    whole.set_title("(a) the whole bar: particles (dots) and local mesh "
                    "(cells) by region; dotted: undeformed outline",
                    fontsize=9.5)

    # Zoom window: the warped particle block with a margin.
    margin = 0.6 * h_p
    window = (warped[:, 0].min() - margin, warped[:, 0].max() + margin,
              warped[:, 1].min() - margin, warped[:, 1].max() + margin)

    # (b) regions.
    draw_mesh(zooms[0], mesh_tints, linewidth=0.6)
    draw_particles(zooms[0], colours=region_colours)
    draw_cracks(zooms[0])
    zooms[0].set_title("(b) regions (no mesh in the centre)", fontsize=9.5)

    # (c) axial displacement, particles and mesh on one colour scale.
    # The scale spans the particles' values: the zoom shows only the block,
    # and the whole bar's range would leave it nearly uniform.
    norm = matplotlib.colors.Normalize(u[:, 0].min(), u[:, 0].max())
    cmap = plt.get_cmap("viridis")
    # The mesh as FE_Q(1) shows it: vertex values, shaded in between.
    triangles = [(q[0], q[k], q[k + 1]) for q in mesh_polygons
                 for k in range(1, len(q) - 1)]
    zooms[1].tripcolor(mesh_warped[:, 0], mesh_warped[:, 1], triangles,
                       m["displacement"][:, 0], shading="gouraud", cmap=cmap,
                       norm=norm, zorder=0.5)
    draw_mesh(zooms[1], "none", linewidth=0.4)
    dots = draw_particles(zooms[1], values=u[:, 0], cmap=cmap, norm=norm)
    draw_cracks(zooms[1])
    bar = figure.colorbar(dots, cax=colourbars[0], orientation="horizontal",
                          format="%.1e", extend="both")
    bar.ax.tick_params(labelsize=7)
    bar.set_label("axial displacement $u_x$ (particles and mesh)",
                  fontsize=8)
    zooms[1].set_title("(c) axial displacement $u_x$", fontsize=9.5)

    # (d) broken bond fraction, mesh in grey.
    draw_mesh(zooms[2], "0.93", linewidth=0.4)
    bnorm = matplotlib.colors.Normalize(0, max(broken.max(), 1e-12))
    dots = draw_particles(zooms[2], values=broken, cmap=plt.get_cmap("magma_r"),
                          norm=bnorm)
    draw_cracks(zooms[2])
    bar = figure.colorbar(dots, cax=colourbars[1], orientation="horizontal")
    bar.ax.tick_params(labelsize=7)
    bar.set_label("fraction of a particle's bonds cut by the crack",
                  fontsize=8)
    zooms[2].set_title("(d) broken bond fraction", fontsize=9.5)

    for axis in [whole] + zooms:
        axis.set_aspect("equal")
        axis.set_xlabel("$x + s\\,u_x$", fontsize=8.5, labelpad=1)
        axis.tick_params(labelsize=7.5)
    whole.set_ylabel("$y + s\\,u_y$", fontsize=8.5)
    zooms[0].set_ylabel("$y + s\\,u_y$", fontsize=8.5)
    all_x = np.concatenate([mesh_warped[:, 0], warped[:, 0], reference[:, 0]])
    all_y = np.concatenate([mesh_warped[:, 1], warped[:, 1], reference[:, 1]])
    whole.set_xlim(all_x.min() - 0.03, all_x.max() + 0.03)
    whole.set_ylim(all_y.min() - 0.03, all_y.max() + 0.03)
    for axis in zooms:
        axis.set_xlim(window[0], window[1])
        axis.set_ylim(window[2], window[3])
    for axis in zooms[1:]:
        axis.set_yticklabels([])
    # The zoom window, marked on the whole bar.
    whole.add_patch(matplotlib.patches.Rectangle(
        (window[0], window[2]), window[1] - window[0], window[3] - window[2],
        fill=False, ec="k", lw=0.8, ls="--", zorder=4))

    handles = [Line2D([], [], marker="o", ls="", markersize=7,
                      markerfacecolor=COLOURS[k], markeredgecolor="0.2",
                      markeredgewidth=0.4,
                      label=f"particle, {k} {REGIONS[k]}")
               for k in sorted(set(region))]
    handles += [Patch(facecolor=overlap_tint, edgecolor="0.55",
                      label="mesh cell, 3 overlap"),
                Patch(facecolor=local_tint, edgecolor="0.55",
                      label="mesh cell, 4 local"),
                Line2D([], [], color="k", lw=1.6, ls=(0, (3, 1.5)),
                       label="crack")]
    figure.legend(handles=handles, loc="upper center", ncol=len(handles),
                  fontsize=8, frameon=False, bbox_to_anchor=(0.5, 0.935),
                  handletextpad=0.3, columnspacing=1.1)

    opening = (f"max crack opening in this slice {max_opening:.2e} "
               f"(drawn as {s * max_opening:.3f})")
    if summary_opening is not None:
        opening += f"; summary.json: {summary_opening:.2e}"
    figure.suptitle(
        f"{name}, {level}: slice z = {z_layer:g} ({len(x)} particles), "
        f"displacement warped \u00d7{s:g}\n{opening}", fontsize=10.5, y=0.995)
    figure.savefig(args.png, dpi=150)
    print(f"wrote {args.png}: {len(x)} particles in the layer z = "
          f"{z_layer:g}, {len(polygons)} mesh cells, warp x{s:g}, "
          f"{opening}")


if __name__ == "__main__":
    main()
