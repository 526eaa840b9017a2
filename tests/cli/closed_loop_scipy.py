"""Issue 43: the closed loop of `whirl export --closed-loop` against an independent one assembled here.

The open-loop plant is `whirl export --drop-azimuth` at the same trimmed wind speed (the multiblade
average without the azimuth). The controller is written from tests/data/rosco/DISCON.IN, read by this
script's own look-up, as transfer functions on the generator speed (ROSCO's Controllers.f90 and
Filters.f90 in continuous time), realized by scipy.signal.tf2ss, and the loop is closed with the
textbook feedback formula. The eigenvalues must agree to 1e-8 relative:
- 14 m/s (region 3): pitch θ = −(K_p + K_i/s) F(s) ω_g with the gains of PC_GS_* at the point's pitch,
  torque τ = −P/(η ω_g²) F(s) ω_g (constant power), F(s) = ω_c/(s + ω_c) (F_LPFCornerFreq);
- 8 m/s (region 2, TSR tracking): torque τ = −(VS_KP + VS_KI/s) F(s) ω_g, pitch held; the reference's
  low pass (F_VSRefSpdCornerFreq) is driven by the wind alone: its pole is appended.
Usage: closed_loop_scipy.py WHIRL SOURCE_DIR WORK_DIR. Exit 77 (skipped) without scipy.
"""
import os
import subprocess
import sys

try:
    import numpy as np
    import scipy.io as sio
    import scipy.signal as sig
except ImportError:
    sys.exit(77)

whirl, root, work = sys.argv[1], sys.argv[2], sys.argv[3]
deck = os.path.join(root, "cases/nrel5mw/Main_ROSCO.fst")


def discon(key):
    """The numbers before the '!' of the DISCON.IN line whose comment starts with `key`."""
    with open(os.path.join(root, "cases/nrel5mw/rosco/DISCON.IN")) as f:
        for line in f:
            values, _, comment = line.partition("!")
            if comment.split()[:1] == [key]:
                return [float(v) for v in values.split()]
    raise KeyError(key)


def export(wind, closed):
    out = os.path.join(work, f"{wind}-{'closed' if closed else 'open'}")
    cmd = [whirl, "export", deck, "--wind", str(wind), "--format", "mat", "--out", out]
    cmd += ["--closed-loop"] if closed else ["--drop-azimuth"]
    subprocess.run(cmd, check=True, capture_output=True)
    return sio.loadmat(os.path.join(out, "statespace.mat"))


def names(m, key):
    return [str(a[0]) for a in m[key].ravel()]


def close(plant, num_tau, num_theta, den):
    """Eigenvalues of the plant closed by [τ; θ] = [num_tau; num_theta]/den · ω_g (one realization)."""
    A, B, C, D = (plant[k][0, 0] for k in "ABCD")
    u, y = names(plant, "u_names"), names(plant, "y_names")
    it, ip, ig = u.index("generator torque"), u.index("collective pitch"), y.index("GenSpeed")
    assert D[ig, it] == 0 and D[ig, ip] == 0
    Ak, Bk, Ck, Dk = sig.tf2ss(np.vstack([num_tau, num_theta]), den)
    Bs, Cg = B[:, [it, ip]], C[[ig], :]
    top = np.hstack([A + Bs @ Dk @ Cg, Bs @ Ck])
    bottom = np.hstack([Bk @ Cg, Ak])
    return np.linalg.eigvals(np.vstack([top, bottom]))


def same_roots(got, expected, label):
    got, expected = list(got), list(expected)
    assert len(got) == len(expected), (label, len(got), len(expected))
    scale = max(abs(z) for z in expected)
    for z in expected:  # greedy nearest match
        k = min(range(len(got)), key=lambda i: abs(got[i] - z))
        err = abs(got[k] - z) / max(abs(z), 1e-3 * scale)
        assert err < 1e-8, f"{label}: root {z} matched {got[k]}, relative error {err:.2e}"
        got.pop(k)


wc = discon("F_LPFCornerFreq")[0]
eta = discon("VS_GenEff")[0] / 100

# Region 3 at 14 m/s.
plant, closed = export(14, False), export(14, True)
pitch = float(closed["BldPitch_deg"].ravel()[0]) * np.pi / 180
kp = np.interp(pitch, discon("PC_GS_angles"), discon("PC_GS_KP"))
ki = np.interp(pitch, discon("PC_GS_angles"), discon("PC_GS_KI"))
w = float(plant["y_ops"][0, 0].ravel()[names(plant, "y_names").index("GenSpeed")])
slope = -discon("VS_RtPwr")[0] / eta / w**2
den = np.polymul([1, 0], [1, wc])  # s (s + ω_c)
ref = close(plant, np.polymul([slope, 0], [wc]), np.polymul([-kp, -ki], [wc]), den)
same_roots(np.linalg.eigvals(closed["A"][0, 0]), ref, "14 m/s")

# Region 2 at 8 m/s.
plant, closed = export(8, False), export(8, True)
vkp, vki = discon("VS_KP")[0], discon("VS_KI")[0]
ref = close(plant, np.polymul([-vkp, -vki], [wc]), [0, 0], den)
ref = np.append(ref, -discon("F_VSRefSpdCornerFreq")[0])
same_roots(np.linalg.eigvals(closed["A"][0, 0]), ref, "8 m/s")
print("ok")
