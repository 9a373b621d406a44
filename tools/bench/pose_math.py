"""Small 3x3 pose algebra and COLMAP's images.txt reader for colmap_compare.sh
(plain Python: the comparison must not need numpy)."""
import math


def quat_to_R(w, x, y, z):
    return [[1-2*(y*y+z*z), 2*(x*y-w*z), 2*(x*z+w*y)],
            [2*(x*y+w*z), 1-2*(x*x+z*z), 2*(y*z-w*x)],
            [2*(x*z-w*y), 2*(y*z+w*x), 1-2*(x*x+y*y)]]


def mul(A, B): return [[sum(A[i][k]*B[k][j] for k in range(3)) for j in range(3)] for i in range(3)]
def T(A): return [list(r) for r in zip(*A)]
def mv(A, v): return [sum(A[i][k]*v[k] for k in range(3)) for i in range(3)]
def sub(u, v): return [u[i]-v[i] for i in range(3)]
def norm(v): return math.sqrt(sum(x*x for x in v))


def angle(u, v):
    """Angle between two vectors, degrees."""
    return math.degrees(math.acos(max(-1, min(1, sum(x*y for x, y in zip(u, v))/(norm(u)*norm(v))))))


def rot_angle(R):
    """Rotation angle of R, degrees."""
    return math.degrees(math.acos(max(-1, min(1, (R[0][0]+R[1][1]+R[2][2]-1)/2))))


def colmap_poses(images_txt):
    """{image name: (R world-to-camera, t)} from COLMAP's images.txt."""
    est = {}
    lines = [l for l in open(images_txt) if not l.startswith('#')]
    for l in lines[0::2]:
        f = l.split()
        if len(f) >= 10:
            est[f[9]] = (quat_to_R(*map(float, f[1:5])), list(map(float, f[5:8])))
    return est


def relative(P, Q):
    """x_Q = R x_P + t for two (R, t) world-to-camera poses."""
    R = mul(Q[0], T(P[0]))
    return R, sub(Q[1], mv(R, P[1]))
