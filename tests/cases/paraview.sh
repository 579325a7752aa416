#!/bin/bash
# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
# ParaView's picture of a case (etc/paraview/coagulationView.py under pvbatch): a 3-D box (the
# slice through its middle, one layer of cells where the middle is a layer of faces) and the
# 1-D duct (seen face on; sliced across when asked), each from a short run and foamToVTK. In each picture the cells' view shows the domain filled with M0's colours
# (viridis) and the particles' view shows the particles' splats (inferno) inside it; a case
# without VTK files and an unknown field are refused (exit 2). Three pictures made at once on
# a busy machine each open their window the first time. A picture pvbatch cannot make fails
# runParaView, or is only a note with COAGULATIONFOAM_PARAVIEW_OPTIONAL=1 (how the tutorials'
# case tests run them). Skipped (exit 77) where pvbatch, or a display or Xvfb, is missing
# (after the check of a failed picture, which brings a pvbatch of its own).
. "$(dirname "$0")/caseLib.sh"

# A pvbatch that starts but cannot make the picture (as Debian's aborts without its display):
# runParaView's error and status 1, as a tutorial's Allrun reports it; with
# COAGULATIONFOAM_PARAVIEW_OPTIONAL=1 a note and status 0
fake="$workDir/paraview_fake"
rm -rf "$fake" && mkdir -p "$fake/bin"
cat > "$fake/bin/pvbatch" <<'EOF'
#!/bin/bash
case " $* " in
    *" --png "*) echo "vtkXOpenGLRenderWindow: bad X server connection. DISPLAY=$DISPLAY. Aborting."
                 kill -ABRT $$ ;;
esac
EOF
chmod +x "$fake/bin/pvbatch"
for optional in 0 1; do
    set +e
    (cd "$fake" && export DISPLAY=:0 PATH="$fake/bin:$PATH" \
        COAGULATIONFOAM_PARAVIEW_OPTIONAL=$optional && runParaView fake.png) > "$fake/log.$optional" 2>&1
    rc=$?
    set -e
    if [ "$optional" = 0 ]; then
        [ "$rc" = 1 ] && grep -q "^ERROR: pvbatch coagulationView.py failed" "$fake/log.0" \
            && grep -q "could not open its window on the X display (DISPLAY=:0)" "$fake/log.0" \
            || { cat "$fake/log.0"; fail "a failed picture: exit $rc, not 1 and an error"; }
    else
        [ "$rc" = 0 ] && grep -q "^NOTE: no ParaView picture" "$fake/log.1" \
            || { cat "$fake/log.1"; fail "a failed picture, optional: exit $rc, not 0 and a note"; }
    fi
done
echo "a failed picture: runParaView's error (exit 1), a note (exit 0) where optional"

pv=$(paraViewCommand) || { echo "ParaView cannot run here: skipped"; exit 77; }
script="$COAGULATIONFOAM_DIR/etc/paraview/coagulationView.py"

# shortCase dir: the duct's inputs for 100 steps of 1e-3 s, one write
shortCase()
{
    setEntry . system/controlDict endTime 0.1
    setEntry . system/controlDict writeInterval 0.1
    setEntry . system/controlDict deltaT 1e-3
}

c=$(newCase constantKernelDuct paraview_box)
cd "$c"
sed -i 's/(50 1 1)/(20 6 6)/; s/^h       0.004;/h       0.05;/; s/type empty;/type wall;/' \
    system/blockMeshDict
sed -i 's/type            empty;/type            slip;/' 0/U
rm -f log.blockMesh && runApplication blockMesh
shortCase
runApplication coagulationFoam
runApplication foamToVTK -latestTime
runParaView box.png --size 1200x800
box=$c/box.png
boxCase=$c
# the slice through the middle of the box's 6 layers, on a layer of faces: one layer's cells
grep -q "the slice z = 0.025 through 120 cells" log.paraView \
    || { cat log.paraView; fail "the box's slice is not one layer of 120 cells"; }

c=$(newCase constantKernelDuct paraview_duct)
cd "$c"
shortCase
runApplication coagulationFoam
runApplication foamToVTK -latestTime
runParaView duct.png --size 1200x800
duct=$c/duct.png
# a slice asked for on a mesh one cell thick: across it, through its 50 cells
paraViewRun "$pv" "$script" --case . --png ductY.png --slice y > log.slice 2>&1 || { cat log.slice; fail "--slice y"; }
grep -q "the slice y = 0.002 through 50 cells" log.slice || { cat log.slice; fail "the duct's slice"; }
# a size with no room for the stacked views above their colour bars: refused, exit 2
rc=0; paraViewRun "$pv" "$script" --case . --png small.png --size 600x400 > log.small 2>&1 || rc=$?
[ "$rc" -eq 2 ] && grep -q "too small for a picture" log.small || { cat log.small; fail "--size 600x400: exit $rc"; }

# the domain's pixels in each view: the picture is the two views stacked (both domains are
# long), each the domain above its colour bar's 200 pixels, scaled to fit 90 % of the view
"$COAGULATIONFOAM_PYTHON" - "$box" 0.2 0.05 "$duct" 0.2 0.004 <<'PY' || fail "the pictures"
import sys
import numpy as np
import matplotlib.image as mpimg
from matplotlib import cm

ok = True
args = sys.argv[1:]
for png, across, up in zip(args[0::3], map(float, args[1::3]), map(float, args[2::3])):
    img = (mpimg.imread(png)[:, :, :3] * 255).round().astype(int)
    h, w, _ = img.shape
    ph, bar = h // 2, 200
    k = min(0.9 * w / across, 0.9 * (ph - bar) / up)
    area = (k * across) * (k * up)
    background = img[2, w // 2]
    # the cells fill the domain in the map's colours; the particles' discs cover a part of it,
    # their edges blended with the background and each other
    for view, cmap, least, mapped in ((0, cm.viridis, 0.9, 0.9), (1, cm.inferno, 0.3, 0.4)):
        part = img[view * ph: view * ph + ph - bar].reshape(-1, 3)
        shown = part[np.any(part != background, axis=1)]
        colours = np.unique(shown, axis=0)
        ref = (cmap(np.linspace(0, 1, 256))[:, :3] * 255)
        # the colours of the map (shading and splat edges blend some with the background)
        dist = np.min(np.linalg.norm(shown[:, None, :] - ref[None, :, :], axis=2), axis=1)
        on_map = np.mean(dist < 12)
        good = len(shown) >= least * area and len(colours) >= 10 and on_map > mapped
        print("%s view %d: %d of %.0f domain pixels drawn, %d colours, %.0f %% on the map: %s"
              % (png, view, len(shown), area, len(colours), 100 * on_map, "ok" if good else "FAIL"))
        ok &= good
sys.exit(0 if ok else 1)
PY

# Three pictures at once on a busy machine (a busy loop per core, 120 s at most), each pvbatch
# on its own Xvfb: each opens its window the first time. Xvfb by default resets when its last
# client leaves, as pvbatch's display test does just before pvbatch opens its window, and
# refuses the window while it resets ("bad X server connection"), the more often the busier
# the machine; virtualDisplay's Xvfb does not reset
load="$workDir/paraview_load"
rm -rf "$load" && mkdir -p "$load"
busy=() renders=()
for ((i = 0; i < $(availableCores); i++)); do
    timeout 120 bash -c 'while :; do :; done' & busy+=($!)
done
for k in 1 2 3; do
    paraViewRun "$pv" "$script" --case "$boxCase" --png "$load/$k.png" --size 1200x800 \
        > "$load/log.$k" 2>&1 & renders+=($!)
done
made=0
for k in 1 2 3; do
    if wait "${renders[k - 1]}" && [ -s "$load/$k.png" ] \
        && ! grep -q -i "bad X server connection\|could not connect" "$load/log.$k"; then
        made=$((made + 1))
    else
        echo "picture $k of 3 at once:"; tail -n 5 "$load/log.$k"
    fi
done
kill "${busy[@]}" 2> /dev/null || :
wait "${busy[@]}" 2> /dev/null || :
echo "pictures made at once on a busy machine, each at the first try: $made of 3"
[ "$made" = 3 ] || fail "pictures at once: $((3 - made)) of 3 not made at the first try"

# refused: a case without VTK files, a field the series does not have
mkdir -p "$workDir/paraview_empty"
set +e
(cd "$workDir/paraview_empty" && paraViewRun "$pv" "$script" --case . --png x.png) > err.log 2>&1
rc=$?
set -e
[ "$rc" = 2 ] && grep -q "run foamToVTK first" err.log || { cat err.log; fail "no VTK: exit $rc"; }
set +e
paraViewRun "$pv" "$script" --case . --field M7 --png y.png > err.log 2>&1
rc=$?
set -e
[ "$rc" = 2 ] && grep -q "no cell field M7" err.log || { cat err.log; fail "unknown field: exit $rc"; }
[ ! -e y.png ] || fail "a picture written for an unknown field"
echo "ParaView pictures: ok"
