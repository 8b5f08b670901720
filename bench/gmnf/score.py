#!/usr/bin/env python3
"""score.py RESULT ORIGINAL: error of a denoised mesh against the noise-free one (same connectivity).

Prints one JSON line:
  mean_normal_error_deg  mean over faces of acos(n . n0) in degrees, n and n0 the unit face normals of
                         RESULT and ORIGINAL (the measure GuidedDenoising calls getMeanSquareAngleError;
                         nothing is squared)
  mean_vertex_distance   mean over vertices of |p - p0|, p0 the vertex of ORIGINAL with the same index
  mean_vertex_distance_rel  the same divided by the mean edge length of ORIGINAL (original_mean_edge_length)
  plus counts: faces, vertices, non_finite_vertices, degenerate_faces (zero-length normal in either mesh;
  they are left out of the normal mean and counted here).
If RESULT has non-finite vertices the two means are computed over the finite part and the line says so;
the caller should treat such a run as failed.

Meshes: ASCII .obj (v/f lines, "i", "i/t", "i//n", "i/t/n", negative indices) or ASCII .off; faces with
more than three corners are fanned into triangles in both meshes the same way.
Needs Python 3 and numpy (Debian: python3-numpy).
"""
import json
import sys

import numpy as np


def _fan(face):
    return [(face[0], face[k], face[k + 1]) for k in range(1, len(face) - 1)]


def read_mesh(path):
    verts, tris = [], []
    low = path.lower()
    with open(path, "r", encoding="utf-8", errors="replace") as f:
        if low.endswith(".obj"):
            for line in f:
                parts = line.split()
                if not parts:
                    continue
                if parts[0] == "v":
                    verts.append([float(x) for x in parts[1:4]])
                elif parts[0] == "f":
                    idx = []
                    for tok in parts[1:]:
                        i = int(tok.split("/")[0])
                        idx.append(i - 1 if i > 0 else len(verts) + i)
                    tris.extend(_fan(idx))
        elif low.endswith(".off"):
            tokens = []
            for line in f:
                tokens.extend(line.split("#", 1)[0].split())
            if not tokens or tokens[0] != "OFF":
                raise ValueError(f"{path}: only plain ASCII OFF is read")
            nv, nf = int(tokens[1]), int(tokens[2])
            pos = 4
            for _ in range(nv):
                verts.append([float(x) for x in tokens[pos:pos + 3]])
                pos += 3
            for _ in range(nf):
                n = int(tokens[pos])
                tris.extend(_fan([int(x) for x in tokens[pos + 1:pos + 1 + n]]))
                pos += 1 + n
                # per-face colours are not supported (they would shift the tokens)
        else:
            raise ValueError(f"{path}: want .obj or .off")
    return np.asarray(verts, dtype=np.float64), np.asarray(tris, dtype=np.int64)


def face_normals(v, t):
    n = np.cross(v[t[:, 1]] - v[t[:, 0]], v[t[:, 2]] - v[t[:, 0]])
    length = np.linalg.norm(n, axis=1)
    ok = np.isfinite(length) & (length > 0)
    n[ok] /= length[ok][:, None]
    return n, ok


def mean_edge_length(v, t):
    """Mean length of the distinct edges of the triangles t (each edge counted once)."""
    e = np.sort(np.concatenate([t[:, [0, 1]], t[:, [1, 2]], t[:, [2, 0]]]), axis=1)
    e = np.unique(e, axis=0)
    return float(np.linalg.norm(v[e[:, 1]] - v[e[:, 0]], axis=1).mean()) if len(e) else float("nan")


def score(result_path, original_path, original_mesh=None):
    """original_mesh: optional (vertices, triangles) of ORIGINAL already read, to skip reading it again."""
    v, t = read_mesh(result_path)
    v0, t0 = original_mesh if original_mesh is not None else read_mesh(original_path)
    if v.shape != v0.shape or t.shape != t0.shape or not np.array_equal(t, t0):
        raise ValueError("RESULT and ORIGINAL do not have the same connectivity "
                         f"({len(v)}/{len(v0)} vertices, {len(t)}/{len(t0)} faces)")
    finite_v = np.isfinite(v).all(axis=1)
    n, ok = face_normals(v, t)
    n0, ok0 = face_normals(v0, t0)
    good = ok & ok0
    cosines = np.clip(np.einsum("ij,ij->i", n[good], n0[good]), -1.0, 1.0)
    angles = np.degrees(np.arccos(cosines))
    dist = np.linalg.norm(v[finite_v] - v0[finite_v], axis=1)
    out = {
        "result": result_path,
        "original": original_path,
        "mean_normal_error_deg": float(angles.mean()) if angles.size else None,
        "mean_vertex_distance": float(dist.mean()) if dist.size else None,
        "vertices": int(len(v)),
        "faces": int(len(t)),
        "non_finite_vertices": int((~finite_v).sum()),
        "degenerate_faces": int((~good).sum()),
    }
    h = mean_edge_length(v0, t0)
    out["original_mean_edge_length"] = h
    out["mean_vertex_distance_rel"] = (out["mean_vertex_distance"] / h
                                       if out["mean_vertex_distance"] is not None and h > 0 else None)
    if out["non_finite_vertices"]:
        out["note"] = "non-finite vertices: means over the finite part only; treat the run as failed"
    return out


def main(argv):
    if len(argv) != 3:
        sys.stderr.write(__doc__)
        return 2
    try:
        print(json.dumps(score(argv[1], argv[2])))
    except (OSError, ValueError) as e:
        sys.stderr.write(f"score.py: {e}\n")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
