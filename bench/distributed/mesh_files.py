# What the distributed benchmarks share: a program run (its wall time; a failure ends the benchmark) and the mesh
# files they make (OFF, read token by token, comments allowed; binary PLY, which anisotropic_fairing_mpi reads and
# writes by blocks, each process holding its part of the mesh).
import struct, subprocess, sys, time

def run(command):
    start = time.perf_counter()
    p = subprocess.run(command, capture_output=True, text=True)
    if p.returncode != 0: sys.exit("failed: %s\n%s" % (" ".join(command), p.stderr))
    return time.perf_counter() - start

def read_off(path):
    words = [w for l in open(path) for w in l.split("#")[0].split()]
    assert words[0] == "OFF"
    n, m = int(words[1]), int(words[2])
    at = 4
    points = [[float(x) for x in words[at + 3 * i:at + 3 * i + 3]] for i in range(n)]
    at += 3 * n
    faces = [[int(x) for x in words[at + 4 * j + 1:at + 4 * j + 4]] for j in range(m)]
    return points, faces

def write_off(path, points, faces):
    with open(path, "w") as out:
        out.write("OFF\n%d %d 0\n" % (len(points), len(faces)))
        out.writelines("%.17g %.17g %.17g\n" % tuple(p) for p in points)
        out.writelines("3 %d %d %d\n" % tuple(t) for t in faces)

def write_binary_ply(path, points, faces):
    with open(path, "wb") as out:
        out.write(("ply\nformat binary_little_endian 1.0\nelement vertex %d\nproperty double x\nproperty double y\n"
                   "property double z\nelement face %d\nproperty list uchar int vertex_indices\nend_header\n"
                   % (len(points), len(faces))).encode())
        out.write(b"".join(struct.pack("<3d", *p) for p in points))
        out.write(b"".join(struct.pack("<B3i", 3, *t) for t in faces))
