"""The cracked plate of parameter_files/lps_plate_2d_crack.prm in a plate of
another size, shared by the benchmarks that compare plates."""


def centred_plate(side):
    """The scene's crack, loading and reference profile centred in a plate
    of side `side` (the file's is 2), with the file's nonlocal region around
    the crack: the crack, a quarter of the file's plate wide, is an eighth
    of a plate of side 4."""
    c = side / 2
    return ["Geometry/Body upper corner=%g, %g" % (side, side),
            "Geometry/Nonlocal region lower corner=%g, %g" % (c - 0.5,
                                                               c - 0.25),
            "Geometry/Nonlocal region upper corner=%g, %g" % (c + 0.5,
                                                               c + 0.25),
            "Cracks/Corners=%g, %g, %g, %g" % (c - 0.25, c, c + 0.25, c),
            "Elasticity data/Boundary data=-1e-3*nu*(1 + nu)/E*(x - %g); "
            "1e-3*(1 - nu^2)/E*(y - %g)" % (c, c),
            "Postprocess/Reference crack opening=4*1e-3/Eprime*"
            "sqrt(max(0.0625 - (x - %g)^2, 0))" % c]
