# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
"""The particles of a case's coagulationCloud, from the ASCII files of a time folder
(writeFormat ascii): <case>/<time>/lagrangian/coagulationCloud/{coordinates,mass,weight,...}.

cells_of_coordinates(text)  each particle's cell from the text of a coordinates file, whose
                            rows are '(a b c d) celli tetFacei tetPti'
scalar_values(text)         the values of a scalar particle field's file (the list after the
                            header)
cell_of(case, time)         cells_of_coordinates of the case's coordinates file
field(case, time, name)     scalar_values of the case's field file NAME (mass, weight, ...)
"""

import numpy as np

CLOUD = "coagulationCloud"


def cloud_file(case, time, name):
    return "%s/%s/lagrangian/%s/%s" % (case, time, CLOUD, name)


def cells_of_coordinates(text):
    """Each particle's cell: the first integer after the barycentric coordinates of each
    row '(a b c d) celli tetFacei tetPti' (rows of one ')' and more than 20 characters)."""
    rows = [l for l in text.splitlines() if l.startswith("(") and l.count(")") == 1 and len(l) > 20]
    return np.array([int(l.split(")")[1].split()[0]) for l in rows], dtype=int)


def scalar_values(text):
    """The list of a scalar field's file: from the first '(' after the line of the header's
    last '}' to the last ')'."""
    start = text.index("(", text.index("\n", text.rindex("}")))
    return np.array(text[start + 1:text.rindex(")")].split(), dtype=float)


def cell_of(case, time):
    """Each particle's cell, from the ASCII coordinates file."""
    with open(cloud_file(case, time, "coordinates")) as f:
        return cells_of_coordinates(f.read())


def field(case, time, name):
    """The scalar particle field NAME (one value a particle, in the coordinates' order)."""
    with open(cloud_file(case, time, name)) as f:
        return scalar_values(f.read())
