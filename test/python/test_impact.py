"""multiple_impact: the engine from masses, contacts and laws. A single frictionless contact's energetic restitution is
Newton's (the textbook two-body collision); a perfectly elastic chain keeps its momentum and energy; friction keeps
every contact's tangential impulse within its cone; bad input raises Error naming the field."""
import math

import numpy as np
import pytest

import billiard_shot_planner as bsp


def test_one_contact_is_the_textbook_collision():
    # Body 1 (1 kg) at 1 m/s into body 2 (2 kg) at rest; the contact's normal from body 1 to body 2 (A is body 2).
    m1, m2, e = 1.0, 2.0, 0.8
    result = bsp.multiple_impact(np.diag([m1, m2]), [1.0, 0.0], [{"normal": [-1.0, 1.0], "restitution": e}])
    expected = [(m1 - e * m2) / (m1 + m2), (1.0 + e) * m1 / (m1 + m2)]  # -0.2 and 0.6 m/s
    assert result.velocity == pytest.approx(expected, abs=1e-9)
    assert result.normal_impulses[0] == pytest.approx(m2 * expected[1], rel=1e-9)
    assert result.ends_of_compression == [1]
    assert result.states[-1] == []


def test_an_elastic_chain_keeps_momentum_and_energy():
    # Three equal balls, the first at 1 m/s into two touching at rest (Newton's cradle), e = 1, equal springs.
    contacts = [{"name": "1-2", "normal": [-1.0, 1.0, 0.0]}, {"name": "2-3", "normal": [0.0, -1.0, 1.0]}]
    result = bsp.multiple_impact(np.eye(3), [1.0, 0.0, 0.0], contacts)
    assert sum(result.velocity) == pytest.approx(1.0, abs=1e-9)
    assert result.final_kinetic_energy == pytest.approx(result.initial_kinetic_energy, rel=1e-9)
    assert 0.5 * float(np.dot(result.velocity, result.velocity)) == pytest.approx(0.5, rel=1e-9)
    # Both contacts act at once: the first state has both active.
    assert set(result.states[0]) == {"1-2", "2-3"}


def test_friction_stays_in_its_cone():
    # A ball (mass 1, radius 1, inertia 0.4 about z; u = vx, vy, vz, wz) hitting the wall y = 0 at 45 degrees: its
    # contact point moves at vx + R wz along x (t1) and at vz along z (t2).
    radius, mu = 1.0, 0.3
    contact = {"normal": [0.0, 1.0, 0.0, 0.0], "tangent": [[1.0, 0.0, 0.0, radius], [0.0, 0.0, 1.0, 0.0]],
               "restitution": 0.9, "friction": mu, "eta2": 1.2}
    result = bsp.multiple_impact(np.diag([1.0, 1.0, 1.0, 0.4]), [1.0, -1.0, 0.0, 0.0], [contact])
    normal, tangential = result.normal_impulses[0], result.tangential_impulses[0]
    assert normal > 0.0
    assert np.linalg.norm(tangential) <= mu * normal * (1 + 1e-9)
    assert tangential[0] < 0.0  # friction opposes the slip along +x
    assert result.final_kinetic_energy <= result.initial_kinetic_energy


@pytest.mark.parametrize(
    "kwargs, field",
    [
        (dict(mass_matrix=[[1.0, 0.0]], velocity=[1.0], contacts=[{"normal": [-1.0]}]), "mass_matrix"),
        (dict(mass_matrix=np.eye(2), velocity=[1.0, math.nan], contacts=[{"normal": [-1.0, 1.0]}]), "velocity"),
        (dict(mass_matrix=np.eye(2), velocity=[1.0, 0.0], contacts=[{"normal": [1.0]}]), "contacts[0].normal"),
        (dict(mass_matrix=np.eye(2), velocity=[1.0, 0.0], contacts=[{"normal": [-1.0, 1.0], "restitution": 1.5}]),
         "contacts[0].restitution"),
        (dict(mass_matrix=np.eye(2), velocity=[1.0, 0.0], contacts=[{"normal": [-1.0, 1.0], "friction": 0.2}]),
         "contacts[0].tangent"),
        (dict(mass_matrix=np.eye(2), velocity=[1.0, 0.0], contacts=[{"normal": [-1.0, 1.0], "colour": 1}]),
         "contacts[0].colour"),
        (dict(mass_matrix=np.eye(2), velocity=[1.0, 0.0],
              contacts=[{"normal": [-1.0, 1.0], "normal_law": {"type": "elastic_plastic", "yield_speed": -1.0}}]),
         "contacts[0].normal_law.yield_speed"),
        (dict(mass_matrix=np.eye(2), velocity=[1.0, 0.0], contacts=[{"normal": [-1.0, 1.0],
                                                                      "normal_law": {"type": "hertz"}}]),
         "contacts[0].normal_law.type"),
        (dict(mass_matrix=np.eye(2), velocity=[-1.0, 0.0], contacts=[{"normal": [-1.0, 1.0]}]), "velocity"),
    ],
)
def test_bad_input_names_the_field(kwargs, field):
    with pytest.raises(bsp.Error) as raised:
        bsp.multiple_impact(**kwargs)
    assert raised.value.field == field
