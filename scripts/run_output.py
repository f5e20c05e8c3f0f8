"""An LtN run's output directory as the per-level plot scripts take it: their
command line, OUTPUT_DIR [LEVEL] [PNG], the files a level writes there, and
the run's name for titles."""
import os
import sys


def level_file(directory, kind, level, extension="pvtu"):
    """The path of the file of `kind` (e.g. "nonlocal_field") that a run
    writes for `level` into `directory`: KIND_level-NN.EXTENSION."""
    return os.path.join(directory, f"{kind}_level-{level:02d}.{extension}")


def level_plot_arguments(png_kind):
    """(directory, level, png) of the command line OUTPUT_DIR [LEVEL] [PNG]:
    the level 0 and the PNG OUTPUT_DIR/PNG_KIND_level-NN.png unless given."""
    directory = sys.argv[1]
    level = int(sys.argv[2]) if len(sys.argv) > 2 else 0
    png = (sys.argv[3] if len(sys.argv) > 3
           else level_file(directory, png_kind, level, "png"))
    return directory, level, png


def run_name(directory):
    """The run's name: the last component of its output directory."""
    return os.path.basename(os.path.normpath(directory))
