"""Which link pairs of a robot are checked for self-collision.

Rigid groups one joint apart are adjacent and never checked; of the rest, a
pair closer than SELF_MARGIN in the robot's default configuration (the
Panda's "ready" pose, otherwise the middle of the joint limits) touches by
construction of the meshes and is left out too.
"""

from __future__ import annotations

import numpy as np

from tampcli.geometry.model import PANDA_READY
from tampcli.geometry.narrow import signed_distance
from tampcli.geometry.pairs import Query

SELF_MARGIN = 0.01  # m: link pairs this close in the default configuration are not checked


def self_collision_pairs(world, link_parts, group, request) -> tuple[tuple[int, int], ...]:
    """Indices (into `link_parts`) of the link-part pairs checked for self-collision;
    `group`: link index -> its rigid group; `request`: the FCL distance request."""
    chain = world.chain
    parent_group = {i: group[link.parent] for i, link in enumerate(chain.links)
                    if link.q_index >= 0}
    query = Query(chain, chain.fk_list(default_configuration(world)), {})
    pairs = []
    for ia, pa in enumerate(link_parts):
        for ib in range(ia + 1, len(link_parts)):
            pb_ = link_parts[ib]
            ga, gb = group[pa.link], group[pb_.link]
            if ga == gb or parent_group.get(ga) == gb or parent_group.get(gb) == ga:
                continue
            a, b = query.placed(ia, pa, None), query.placed(ib, pb_, None)
            if signed_distance(request, a, pa.obj, b, pb_.obj)[0] > SELF_MARGIN:
                pairs.append((ia, ib))
    return tuple(pairs)


def default_configuration(world) -> np.ndarray:
    if world.scene.robot.model == "panda":
        return np.array(PANDA_READY)
    mid = 0.5 * (world.lower + world.upper)
    return np.where(np.isfinite(mid), mid, 0.0)
