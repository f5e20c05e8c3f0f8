"""What the stability-map scripts share: the couplings they compare (label:
their `Coupling/Method`) and the one line a failed run reports."""

# LtN by its reduced-space CG (its iterations are the ones that can grow);
# the baselines as doc/baseline_couplings.md defines them (blending: in 1D
# on the shared mesh, in 2D on the particle lattice of the whole body).
COUPLINGS = {"LtN": "reduced space cg",
             "Schwarz": "alternating schwarz",
             "Schwarz + Aitken": "alternating schwarz aitken",
             "force blending": "force blending",
             "energy blending": "energy blending"}
# The LPS axes (poisson_ratio.py): blending is for diffusion only.
COUPLINGS_LPS = {label: method for label, method in COUPLINGS.items()
                 if not method.endswith("blending")}


def failure_line(error):
    """The last line a run that failed (a subprocess.CalledProcessError of
    run_ltn) wrote to stderr: ltn's one-line error or failure."""
    lines = error.stderr.decode().strip().splitlines()
    return lines[-1] if lines else f"exit {error.returncode}"
