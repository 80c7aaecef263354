"""The strike from Python, against physics written out here: a level centre hit is the collision of two free bodies
(Newton's, the cue's restitution), sends the ball along the cue without spin about z; right english spins it
counter-clockwise and squirts it left (docs/stroke_conventions.md); the conventions' converters invert each other."""
import math
import threading

import numpy as np
import pytest

import billiard_shot_planner as bsp


def test_a_level_centre_hit_is_the_collision_of_two_free_bodies():
    config = bsp.Configuration()
    phi, speed = math.radians(30.0), 2.0
    result = bsp.strike(bsp.Stroke(phi=phi, speed=speed), cue_ball=(0.1, -0.2), configuration=config)
    m_cue, m_ball, e = config["cue_mass"], config["ball_mass"], config["cue_contact/restitution"]
    expected = (1.0 + e) * m_cue / (m_cue + m_ball) * speed
    velocity = np.asarray(result.velocity)
    # The cloth's friction over the ~1 ms contact takes at most mu * g * 2 ms = 0.004 m/s.
    assert np.linalg.norm(velocity) == pytest.approx(expected, abs=0.01)
    assert math.atan2(velocity[1], velocity[0]) == pytest.approx(phi, abs=1e-9)
    assert result.angular_velocity[2] == pytest.approx(0.0, abs=1e-9)
    assert result.states[-1] == "S4"  # the cue and the ball part
    assert not result.miscue


def test_right_english_spins_the_ball_counter_clockwise_and_squirts_it_left():
    result = bsp.strike(bsp.Stroke(phi=0.0, speed=2.0, a=0.4))
    assert result.angular_velocity[2] > 1.0
    assert result.velocity[1] > 0.0  # left of a cue heading +x
    mirrored = bsp.strike(bsp.Stroke(phi=0.0, speed=2.0, a=-0.4))
    assert mirrored.angular_velocity[2] == pytest.approx(-result.angular_velocity[2], rel=1e-9)
    assert mirrored.velocity[1] == pytest.approx(-result.velocity[1], rel=1e-9)


def test_the_converters_invert_each_other_and_keep_the_side_of_english():
    stroke = bsp.Stroke(phi=0.3, theta=0.1, speed=2.5, a=0.2, b=-0.3)
    V0, phi, theta, a, b = bsp.to_pooltool(stroke)
    assert a == pytest.approx(-0.2)  # pooltool's a > 0 is the left of the ball
    assert (V0, theta) == pytest.approx((2.5, math.degrees(0.1)))
    back = bsp.from_pooltool(V0, phi, theta, a, b)
    assert (back.phi, back.theta, back.speed, back.a, back.b) == pytest.approx((0.3, 0.1, 2.5, 0.2, -0.3))
    fa, fb, ftheta, fphi, v = bsp.to_fastfiz(stroke)
    assert fa == pytest.approx(0.2 * 28.575)  # millimetres, + right
    again = bsp.from_fastfiz(fa, fb, ftheta, fphi, v)
    assert (again.phi, again.a, again.b) == pytest.approx((0.3, 0.2, -0.3))


@pytest.mark.parametrize(
    "stroke, field",
    [
        (bsp.Stroke(a=1.2), "a"),
        (bsp.Stroke(phi=math.nan), "phi"),
        (bsp.Stroke(theta=2.0), "theta"),
    ],
)
def test_a_stroke_off_the_ball_or_not_finite_is_refused_by_name(stroke, field):
    with pytest.raises(bsp.Error) as raised:
        bsp.strike(stroke)
    assert raised.value.code == "invalid_argument"
    assert raised.value.field == field


def test_strikes_on_several_threads_give_the_same_answers():
    strokes = [bsp.Stroke(phi=0.1 * k, speed=1.0 + 0.1 * k, a=0.02 * k) for k in range(8)]
    alone = [bsp.strike(s).velocity for s in strokes]
    together = [None] * len(strokes)

    def run(k):
        together[k] = bsp.strike(strokes[k]).velocity

    threads = [threading.Thread(target=run, args=(k,)) for k in range(len(strokes))]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for a, b in zip(alone, together):
        assert np.array_equal(a, b)
