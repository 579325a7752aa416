# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
# Sourced by the benchmarks: makeScaleBox DIR makes, in DIR, the 2-D sheared box of the scale
# issue (19): 50 x 10 cells on 0.5 x 0.1, u(y) = 1 + y/H, nut = 1e-5 (1 + 9 y/H) (for a
# turbulent walk), rebound walls, the constant-kernel duct's settings (constant kernel,
# inception everywhere), blockMesh run, no function objects. Needs etc/functions sourced.
makeScaleBox()
{
    local base="$1"
    cp -r "$COAGULATIONFOAM_DIR/tutorials/constantKernelDuct" "$base"
    (
    cd "$base" || exit 1
    cleanCase
    "$COAGULATIONFOAM_PYTHON" - <<'PY'
import numpy as np
nx, ny, L, H = 50, 10, 0.5, 0.1
open("system/blockMeshDict", "w").write("""FoamFile { version 2.0; format ascii; class dictionary; object blockMeshDict; }
vertices ( (0 0 0) (%g 0 0) (%g %g 0) (0 %g 0) (0 0 0.01) (%g 0 0.01) (%g %g 0.01) (0 %g 0.01) );
blocks ( hex (0 1 2 3 4 5 6 7) (%d %d 1) simpleGrading (1 1 1) );
boundary ( inlet { type patch; faces ((0 4 7 3)); } outlet { type patch; faces ((1 2 6 5)); }
  walls { type wall; faces ((0 1 5 4) (3 7 6 2)); } frontAndBack { type empty; faces ((0 3 2 1) (4 5 6 7)); } );
""" % (L, L, H, H, L, L, H, H, nx, ny))
yc = (np.arange(ny) + 0.5) * H / ny
u = np.tile((1 + yc / H)[:, None], (1, nx)).ravel()
nut = np.tile((1e-5 * (1 + 9 * yc / H))[:, None], (1, nx)).ravel()
vec = lambda us: " ".join("(%.12g 0 0)" % v for v in us)
open("0/U", "w").write("""FoamFile { version 2.0; format ascii; class volVectorField; object U; }
dimensions [0 1 -1 0 0 0 0]; internalField nonuniform List<vector> %d (%s);
boundaryField { inlet { type fixedValue; value nonuniform List<vector> %d (%s); } outlet { type zeroGradient; }
  walls { type fixedValue; value nonuniform List<vector> %d (%s); } frontAndBack { type empty; } }
""" % (len(u), vec(u), ny, vec(1 + yc / H), 2 * nx, vec([1.0] * nx + [2.0] * nx)))
open("0/nut", "w").write("""FoamFile { version 2.0; format ascii; class volScalarField; object nut; }
dimensions [0 2 -1 0 0 0 0]; internalField nonuniform List<scalar> %d (%s);
boundaryField { inlet { type zeroGradient; } outlet { type zeroGradient; } walls { type zeroGradient; } frontAndBack { type empty; } }
""" % (len(nut), " ".join("%.12g" % v for v in nut)))
PY
    runApplication blockMesh > /dev/null
    foamDictionary -entry functions -remove system/controlDict > /dev/null
    foamDictionary -entry deltaT -set 1e-3 system/controlDict > /dev/null
    foamDictionary -entry sampling/tRelax -set 100 constant/coagulationProperties > /dev/null
    )
}
