"""Motion core: skeleton, rotations, kinematics, BVH and Acclaim I/O, retargeting, features,
metrics and pose codes. numpy only: the server runs without torch."""
