#!/bin/sh
# Writes the scene-creation benchmark of issue 13: a bumpy latitude-longitude sphere of 708 rings x 708
# segments (2*708*707 = 1,001,112 triangles, 500,558 vertices) as an OBJ, and a scene that renders it.
#   bench/scene_creation/make_big_mesh.sh [OUTDIR] [normals|uvs]
# With neither, the OBJ has only v and f lines (about 37 MB, like a raw scan); "normals" adds vn lines and
# v//vn faces (77 MB), "uvs" vt and vn lines and v/vt/vn faces (the tangent path; 105 MB). Then, e.g.:
#   /usr/bin/time -v build/app/trazo --render OUTDIR/big_mesh.scene --spp 1 --threads 2 --width 64 --height 64 \
#       --stats s.json
set -eu
out=${1:-/tmp/trazo_big_mesh}
normals=${2:-}
mkdir -p "$out"
python3 - "$out/big_mesh.obj" "$normals" <<'PY'
import math, sys
path, normals, uvs = sys.argv[1], sys.argv[2] in ("normals", "uvs"), sys.argv[2] == "uvs"
rings, segs, bump = 708, 708, 0.08
def radius(th, ph):
    return 1.0 + bump * (0.5 * math.sin(7 * th + 1.3) * math.sin(5 * ph) + 0.3 * math.sin(13 * th) * math.cos(11 * ph + 0.7))
verts = [(0.0, 1.0 + 0.0, 0.0)]
for i in range(1, rings):
    th = math.pi * i / rings
    for j in range(segs):
        ph = 2 * math.pi * j / segs
        r = radius(th, ph)
        verts.append((r * math.sin(th) * math.cos(ph), r * math.cos(th), r * math.sin(th) * math.sin(ph)))
verts.append((0.0, -1.0, 0.0))
south = len(verts)  # 1-based index of the south pole
with open(path, "w") as f:
    f.write("# bumpy sphere, %d rings x %d segments\n" % (rings, segs))
    f.write("".join("v %.6f %.6f %.6f\n" % v for v in verts))
    if normals:
        f.write("".join("vn %.6f %.6f %.6f\n" % (x / math.sqrt(x*x+y*y+z*z), y / math.sqrt(x*x+y*y+z*z), z / math.sqrt(x*x+y*y+z*z)) for x, y, z in verts))
    if uvs:  # longitude, latitude
        uv = [(0.5, 1.0)] + [(j / segs, 1 - i / rings) for i in range(1, rings) for j in range(segs)] + [(0.5, 0.0)]
        f.write("".join("vt %.6f %.6f\n" % t for t in uv))
    def ring(i, j):  # 1-based index of vertex j of ring i (1..rings-1)
        return 2 + (i - 1) * segs + (j % segs)
    lines = []
    if uvs:
        fmt = "f %d/%d/%d %d/%d/%d %d/%d/%d\n"
    else:
        fmt = "f %d//%d %d//%d %d//%d\n" if normals else "f %d %d %d\n"
    def tri(a, b, c):
        lines.append(fmt % ((a, a, a, b, b, b, c, c, c) if uvs else (a, a, b, b, c, c) if normals else (a, b, c)))
    for j in range(segs):
        tri(1, ring(1, j + 1), ring(1, j))
    for i in range(1, rings - 1):
        for j in range(segs):
            a, b, c, d = ring(i, j), ring(i, j + 1), ring(i + 1, j + 1), ring(i + 1, j)
            tri(a, b, c)
            tri(a, c, d)
    for j in range(segs):
        tri(south, ring(rings - 1, j), ring(rings - 1, j + 1))
    f.write("".join(lines))
PY
cat > "$out/big_mesh.scene" <<'SCENE'
# Scene creation benchmark (bench/scene_creation/make_big_mesh.sh): a 1M-triangle OBJ under an area light.
SceneSettings
{
    BackgroundColor 0.1 0.1 0.1
    RenderWidth 256
    RenderHeight 256
    Antialiasing 1
}

Camera
{
    POV 0 0 4
    POI 0 0 0
    FOV 45
}

Material
{
    Name matGrey
    DiffuseColor 0.8 0.8 0.8
    SpecularColor 0.2 0.2 0.2
    Roughness 0.5
}

Mesh
{
    Material matGrey
    Source "big_mesh.obj"
}

AreaLight
{
    Color 1 1 1
    Position 0 4 4
    Direction 0 -1 -1
    Width 1
    Height 1
    Subdivision 4 4
}
SCENE
ls -l "$out"
