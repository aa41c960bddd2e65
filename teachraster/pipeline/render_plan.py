"""The render plan: which effects a scene needs, whether each ran, for how much, and why.

``render`` simulates only what the scene calls for (perspective correction only where w
differs, clipping only for triangles that cross a plane, the depth test only where
fragments of two triangles land on one pixel, attributes only at visible pixels, culling
only on request) and reports each decision here, so a lesson can print it.
"""

from __future__ import annotations

from dataclasses import dataclass

#: Effects that ``force=`` can switch on everywhere, for comparison.
FORCEABLE = ("clipping", "perspective", "depth_test", "attributes")


@dataclass(frozen=True)
class Effect:
    """One effect of the pipeline and what the plan did with it.

    ``count`` of ``total`` ``unit`` (e.g. 3 of 120 triangles) is how much it ran for.
    """

    name: str
    ran: bool
    count: int
    total: int
    unit: str
    why: str
    forced: bool = False

    def __str__(self) -> str:
        state = "forced" if self.forced else ("ran" if self.ran else "skipped")
        # "applied to" so that "skipped, applied to 0 of 12" cannot read as "none skipped"
        amount = f"applied to {self.count:>8,} of {self.total:>9,} {self.unit:<10}"
        return f"{self.name:<11} {state:<7} {amount} {self.why}"


@dataclass(frozen=True)
class Plan:
    """The effects of one render, in pipeline order."""

    effects: tuple[Effect, ...]

    def __getitem__(self, name: str) -> Effect:
        for effect in self.effects:
            if effect.name == name:
                return effect
        raise KeyError(f"no effect {name!r}; effects are {[e.name for e in self.effects]}")

    def __iter__(self):
        return iter(self.effects)

    def __str__(self) -> str:
        return "\n".join(str(effect) for effect in self.effects)


def parse_force(force) -> frozenset[str]:
    """``force`` as a set of effect names: None, "all", one name or an iterable of names."""
    if force is None:
        return frozenset()
    if force == "all":
        return frozenset(FORCEABLE)
    try:
        names = {force} if isinstance(force, str) else set(force)
    except TypeError:
        raise TypeError(
            f"force must be None, 'all', an effect name or names, got {force!r}"
        ) from None
    unknown = names - set(FORCEABLE)
    if unknown:
        raise ValueError(f"force: unknown effect(s) {sorted(unknown)}; choose from {FORCEABLE}")
    return frozenset(names)
