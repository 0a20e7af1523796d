"""A NEAT network's graph genome as tables: esc.Network (docs/neat.md)."""

from dataclasses import dataclass

import numpy as np
import pandas as pd

from esc import _esc


@dataclass(frozen=True, eq=False)
class Network:
    """A NEAT network's genome (docs/neat.md), as Run.best_genome returns it for a `neat(...)`
    controller. `nodes`: a DataFrame of `id`, `kind` ("input", "bias", "hidden" or "output")
    and `activation`, by id, sensors first. `links`: a DataFrame of `in`, `out`, `weight`,
    `enabled` and `innovation`, by innovation. `encoded()` is its flat form, the one runs
    store; esc.evaluate and esc.measure take either. Network.decode(flat) reads a flat form
    (ValueError when it is not a graph genome)."""

    nodes: pd.DataFrame
    links: pd.DataFrame

    @staticmethod
    def decode(flat) -> "Network":
        d = _esc.decode_graph(np.asarray(flat, dtype=np.float64))
        nodes = pd.DataFrame({"id": d["id"], "kind": d["kind"], "activation": d["activation"]})
        links = pd.DataFrame({"in": d["in"], "out": d["out"], "weight": d["weight"], "enabled": d["enabled"],
                              "innovation": d["innovation"]})
        return Network(nodes, links)

    def encoded(self) -> np.ndarray:
        """The flat form (a float64 array); ValueError when the tables are not a graph genome
        (a link at an unknown node, two bias nodes, ...), in the codec's words."""
        n, l = self.nodes, self.links
        return _esc.encode_graph(n["id"].to_numpy(np.int64), [str(k) for k in n["kind"]],
                                 [str(a) for a in n["activation"]], l["in"].to_numpy(np.int64),
                                 l["out"].to_numpy(np.int64), l["weight"].to_numpy(np.float64),
                                 l["enabled"].to_numpy(bool), l["innovation"].to_numpy(np.int64))

    @property
    def hidden_nodes(self) -> int:
        return int((self.nodes["kind"] == "hidden").sum())

    @property
    def enabled_links(self) -> int:
        return int(self.links["enabled"].sum())

    def __repr__(self) -> str:
        inputs = int((self.nodes["kind"] == "input").sum())
        outputs = int((self.nodes["kind"] == "output").sum())
        return (f"<esc.Network {inputs} inputs, {self.hidden_nodes} hidden, {outputs} outputs; "
                f"{self.enabled_links} of {len(self.links)} links enabled>")
