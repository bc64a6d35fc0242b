"""Acclaim ASF/AMC reader and FK: a hand-made skeleton with answers worked out by hand, and
real HDM05 files (tests/fixtures/raw, made by tests/fixtures/make_fixtures.py)."""


import numpy as np
import pytest

from interplay.motion.formats.acclaim import forward_kinematics, load_acclaim, read_amc, read_asf
from tests.helpers.paths import RAW as RAW_ROOT

RAW = RAW_ROOT / "hdm05"
SQUAT = RAW / "squat1Reps" / "HDM_bd_squat1Reps_003_120.amc"
JOG = RAW / "jogLeftCircle4StepsRstart" / "HDM_bd_jogLeftCircle4StepsRstart_001_120.amc"
BD = RAW / "asf" / "HDM_bd.asf"

TINY_ASF = """# a two-bone skeleton
:version 1.10
:name tiny
:units
  mass 1.0
  length 0.5
  angle {angle}
:root
   order TX TY TZ RX RY RZ
   axis XYZ
   position 0 0 0
   orientation 0 0 0
:bonedata
  begin
     id 1
     name spine
     direction 0 2 0
     length 2
     axis 0 0 0 XYZ
     dof {spine_dofs}
     limits (-180 180)
            (-180 180)
  end
  begin
     id 2
     name arm
     direction 1 0 0
     length 1
     axis 0 0 {quarter} XYZ
     dof rx
     limits (-180 180)
  end
:hierarchy
  begin
    root spine
    spine arm
  end
"""


def tiny_asf(angle="deg", spine_dofs="rx rz"):
    quarter = "90" if angle == "deg" else str(np.pi / 2)
    return read_asf(TINY_ASF.format(angle=angle, spine_dofs=spine_dofs, quarter=quarter))


def tiny_amc(frames, header=":DEGREES"):
    lines = [":FULLY-SPECIFIED", header]
    for i, (root, spine, arm) in enumerate(frames, start=1):
        lines += [str(i), "root " + " ".join(map(str, root)), "spine " + " ".join(map(str, spine)),
                  f"arm {arm}"]
    return read_amc("\n".join(lines) + "\n")


def test_tiny_skeleton_known_positions():
    asf = tiny_asf()
    assert asf.names == ("root", "spine", "arm")
    assert asf.metres_per_unit == pytest.approx(0.0254 / 0.5)
    np.testing.assert_allclose(asf.bones["spine"].direction, [0, 1, 0])  # normalised
    amc = tiny_amc([((1, 2, 3, 0, 0, 0), (0, 0), 0),
                    ((0, 0, 0, 0, 90, 0), (0, 90), 90)])
    pos, names = forward_kinematics(asf, amc)
    assert names == asf.names and pos.shape == (2, 3, 3)
    # Rest: the spine goes up 2 from the root, the arm 1 along +x.
    np.testing.assert_allclose(pos[0], [[1, 2, 3], [1, 4, 3], [2, 4, 3]], atol=1e-12)
    # Root turned 90° about +y; spine rz 90 tips it to -x (then the root's turn takes -x to +z);
    # the arm's axis (90° about z) makes its rx a turn about the spine's y: +x → -z → -z → -x.
    np.testing.assert_allclose(pos[1], [[0, 0, 0], [0, 0, 2], [-1, 0, 2]], atol=1e-12)


def test_dof_order_is_application_order():
    # "rx rz": x first, then z: up → +z (rx 90) → stays +z (rz 90). "rz rx": up → -x → -x.
    for dofs, expected in (("rx rz", [0, 0, 2]), ("rz rx", [-2, 0, 0])):
        pos, _ = forward_kinematics(tiny_asf(spine_dofs=dofs), tiny_amc([((0,) * 6, (90, 90), 0)]))
        np.testing.assert_allclose(pos[0, 1], expected, atol=1e-12)


def test_radians_from_asf_or_amc_header():
    deg = forward_kinematics(tiny_asf(), tiny_amc([((0, 0, 0, 0, 90, 0), (0, 90), 90)]))[0]
    q = np.pi / 2
    # ASF in radians, AMC without a unit header: the ASF unit applies.
    rad = forward_kinematics(tiny_asf("rad"), tiny_amc([((0, 0, 0, 0, q, 0), (0, q), q)], header=""))[0]
    np.testing.assert_allclose(rad, deg, atol=1e-12)
    # AMC header overrides.
    rad2 = forward_kinematics(tiny_asf(), tiny_amc([((0, 0, 0, 0, q, 0), (0, q), q)], header=":RADIANS"))[0]
    np.testing.assert_allclose(rad2, deg, atol=1e-12)


def test_bad_input_raises_readable_errors():
    with pytest.raises(ValueError, match="hierarchy"):
        read_asf(TINY_ASF.format(angle="deg", spine_dofs="rx rz", quarter="90")
                 .replace("spine arm", "spine arm leg"))
    with pytest.raises(ValueError, match="angle unit"):
        read_asf(TINY_ASF.format(angle="grad", spine_dofs="rx rz", quarter="90"))
    with pytest.raises(ValueError, match="values"):
        forward_kinematics(tiny_asf(), tiny_amc([((0,) * 6, (1, 2, 3), 0)]))
    with pytest.raises(ValueError, match="no frames"):
        read_amc(":FULLY-SPECIFIED\n:DEGREES\n")


def test_hdm05_asf_parsed():
    asf = read_asf(BD)
    assert asf.length_scale == 0.45 and asf.angle_unit == "deg"
    assert len(asf.bones) == 30 and asf.names[0] == "root"
    assert asf.root_order == ("TX", "TY", "TZ", "RX", "RY", "RZ")
    femur = asf.bones["lfemur"]
    assert femur.dofs == ("rx", "ry", "rz") and femur.limits[0] == (-160.0, 20.0)
    np.testing.assert_allclose(np.degrees(femur.axis), [0, 0, 20])
    # Parents come before children.
    seen = {"root"}
    for bone in asf.bones:
        assert asf.parents[bone] in seen
        seen.add(bone)


def test_hdm05_fk_rigid_and_human_sized():
    named, asf, amc = load_acclaim(SQUAT, BD)
    assert amc.n_frames > 60 and named["root"].shape == (amc.n_frames, 3)
    m = asf.metres_per_unit
    for bone, b in asf.bones.items():
        length = np.linalg.norm(named[bone] - named[asf.parents[bone]], axis=-1)
        np.testing.assert_allclose(length, b.length, rtol=1e-9)
    # Standing first frame: top of the head to the lowest foot point is a person's height.
    feet = np.min([named[k][0, 1] for k in ("lfoot", "rfoot", "ltoes", "rtoes")])
    assert 1.5 < (named["head"][0, 1] - feet) * m < 1.9
    assert 0.35 < asf.bones["lfemur"].length * m < 0.5


def test_hdm05_stance_feet_do_not_slide():
    """The convention (R = Rz·Ry·Rx for "XYZ", L = C·M·C⁻¹) keeps planted feet still in a
    jog (median 0.12 m/s); the reverse rotation order slides them at 0.31 m/s, C⁻¹·M·C at 1.1."""
    named, asf, _ = load_acclaim(JOG, BD)
    m, fps = asf.metres_per_unit, 120
    feet = np.stack([named[k] for k in ("lfoot", "rfoot", "ltoes", "rtoes")], axis=1) * m  # (T, 4, 3)
    floor = np.percentile(feet[..., 1], 2)
    planted = (feet[1:, :, 1] < floor + 0.05) & (feet[:-1, :, 1] < floor + 0.05)
    speed = np.linalg.norm(np.diff(feet[..., [0, 2]], axis=0), axis=-1) * fps
    assert planted.mean() > 0.1
    assert np.median(speed[planted]) < 0.2
    # Meanwhile the body does travel.
    assert np.linalg.norm(named["root"][-1, [0, 2]] - named["root"][0, [0, 2]]) * m > 1.0
