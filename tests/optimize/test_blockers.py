"""Blockers read from the NLPs' worst-row messages."""

from tampcli.optimize.blockers import blocker_of
from tampcli.search.learned import Blocker

MOVABLE = frozenset({"a", "b", "c"})


def test_an_overlap_at_a_placement_blames_the_other_body():
    assert blocker_of("placements: (place a goal): overlaps b by 1.2 cm", MOVABLE) == \
        Blocker("b", "(place a goal)")


def test_a_collision_on_the_way_to_an_action_blames_the_body_in_it():
    worst = "motion 2 before (pick a floor): collision panda_hand vs c (margin 1 cm) by 0.4 cm"
    assert blocker_of(worst, MOVABLE) == Blocker("c", "(pick a floor)")


def test_a_carried_object_hitting_a_movable_body():
    worst = "motion 1 before (place a goal): collision a vs b (margin 1 cm) by 2.0 cm"
    assert blocker_of(worst, MOVABLE) == Blocker("b", "(place a goal)")


def test_fixed_bodies_and_the_actions_own_objects_are_no_blockers():
    assert blocker_of("(place a goal): overlaps wall by 1.0 cm", MOVABLE) is None
    assert blocker_of("motion 0 before (pick a floor): collision panda_hand vs a by 1 cm",
                      MOVABLE) is None
    assert blocker_of("(place a goal): footprint outside region goal by 1 cm", MOVABLE) is None
    assert blocker_of(None, MOVABLE) is None


def test_a_push_that_cannot_go_from_where_its_object_stands_blames_the_object():
    """No face's cone leads into the target from the object's pose: the skeletons
    that move it elsewhere before that push come next (gen1's planar instances)."""
    worst = ("(push a home goal bench): motion not into the pushed face (a drag) by 7.1 cm")
    assert blocker_of(worst, MOVABLE) == Blocker("a", "(push a home goal bench)")
    relaxed = ("(push b home goal bench): motion not into the pushed face (no pushed face's "
               "friction cone leads into the target (a drag or a pull))")
    assert blocker_of(relaxed, MOVABLE) == Blocker("b", "(push b home goal bench)")
    # Two movable arguments: which one is pushed is not known from the name alone.
    assert blocker_of("(push a b goal): motion not into the pushed face by 1 cm",
                      MOVABLE) is None


def test_a_collision_with_a_body_that_never_moves_names_the_action():
    from tampcli.optimize.blockers import fixed_obstacle_of

    worst = ("motion 5 before (push b home3 goal3 bench): collision planar_body vs wall2 "
             "(margin 1 mm) by 6.0 cm")
    assert fixed_obstacle_of(worst, MOVABLE) == "(push b home3 goal3 bench)"
    # A movable body in the way is a blocker, not the scene's geometry.
    assert fixed_obstacle_of("motion 2 before (push a x y bench): collision planar_body vs b "
                             "(margin 1 mm) by 4.3 cm", MOVABLE) is None
    assert fixed_obstacle_of("(place a goal): overlaps wall by 1.0 cm", MOVABLE) is None
    assert fixed_obstacle_of(None, MOVABLE) is None
