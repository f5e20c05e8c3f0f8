#!/usr/bin/env python3
"""The folders of LtN are layers: each may include only the folders below it
(doc/architecture.md). This prints the folder graph of the includes and fails
on an include that goes up or sideways, which is also how a cycle between
folders would begin.

usage: python3 scripts/check_layers.py [REPOSITORY]
"""
import collections
import pathlib
import re
import sys

# Each folder with the folders it may include, bottom to top. coupling/ is
# three layers of its own: the optimality system, its preconditioners, the
# solvers; above it, `coupling` stands for all three.
COUPLING = {'coupling/system', 'coupling/preconditioners', 'coupling/solvers'}
ALLOWED = {
    'base': set(),
    'problem': {'base'},
    'local': {'base', 'problem'},
    'nonlocal': {'base', 'problem'},
    'model_solvers': {'base'},
    'coupling/system': {'base', 'problem', 'local', 'nonlocal',
                        'model_solvers'},
    'coupling/preconditioners': {'base', 'problem', 'local', 'nonlocal',
                                 'model_solvers', 'coupling/system'},
    'coupling/solvers': {'base', 'problem', 'local', 'nonlocal',
                         'model_solvers', 'coupling/system',
                         'coupling/preconditioners'},
    'output': {'base', 'problem', 'local', 'nonlocal'},
    'scene': {'base', 'problem', 'local', 'nonlocal', 'model_solvers',
              'output'} | COUPLING,
    'app': {'base', 'problem', 'local', 'nonlocal', 'model_solvers',
            'output', 'scene'} | COUPLING,
}

INCLUDE = re.compile(r'^\s*#\s*include\s*[<"]ltn/([a-z_/]+)/[a-z_.]+[>"]',
                     re.MULTILINE)


def layer(folder_parts):
    """The layer of a file in the folders @p folder_parts."""
    if folder_parts[0] == 'coupling' and len(folder_parts) > 1:
        return 'coupling/' + folder_parts[1]
    return folder_parts[0]


def main():
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else '.')
    edges = collections.defaultdict(collections.Counter)
    errors = []
    for top, pattern in ((root / 'include' / 'ltn', '*.h'),
                         (root / 'source', '*.cc')):
        for path in sorted(top.rglob(pattern)):
            folder = layer(path.relative_to(top).parts[:-1] or ('.',))
            if folder not in ALLOWED:
                errors.append(f'{path}: folder {folder} is not a layer of '
                              'scripts/check_layers.py')
                continue
            for target in INCLUDE.findall(path.read_text()):
                target = layer(target.split('/'))
                if target == folder:
                    continue
                edges[folder][target] += 1
                if target not in ALLOWED[folder]:
                    errors.append(f'{path}: {folder}/ includes {target}/')
    for folder in ALLOWED:
        targets = ', '.join(f'{t} ({n})' for t, n in sorted(edges[folder].items()))
        print(f'{folder:26s} -> {targets or "-"}')
    for error in errors:
        print('not allowed:', error)
    return 1 if errors else 0


if __name__ == '__main__':
    sys.exit(main())
