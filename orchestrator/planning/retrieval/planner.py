"""The retrieval planner: the nearest bank examples' calls, adapted to this request's names.

The request is embedded with MiniLM; the NEAREST closest examples (generated and learned)
are each adapted (retrieval/slots.py: this request's categories, places, numbers and asset
ids put in place of the example's), scored, and the best one that a dry run accepts is the
plan. Its confidence is the similarity less a penalty for every slot the request did not
fill (the example's value was kept) and every name or number the request said that the
example has no place for.
"""

from __future__ import annotations

import time

from drivetwin.orchestrator.planning.base import Plan, PlanContext, PlanningError, TraceStep
from drivetwin.orchestrator.planning.retrieval.index import BankIndex, Hit, bank_index
from drivetwin.orchestrator.planning.retrieval.slots import REFERENCES, Adapted, Slots, adapt, intents, read_slots

PROMPT_VERSION = "retrieval-2"
# Examples adapted per request: enough to find one whose slots fit, few enough to stay fast.
NEAREST = 12
# Confidence lost per example slot the request left unfilled, and per request slot unused.
UNFILLED_PENALTY = 0.12
UNUSED_PENALTY = 0.1
# A request that points back at the conversation ("put one there") is for the rules/LLM.
REFERENCE_PENALTY = 0.3
# Per amount left to the tool's default because the request did not state one.
DROPPED_PENALTY = 0.04
# An example this similar is the request itself (a learned one, say): its calls as they are.
VERBATIM_SIMILARITY = 0.98
# Per slot filled from another kind (an existing asset for a category the request named).
STAND_IN_PENALTY = 0.1
# Per intent marker (removal, question) that the request and the example do not share:
# "remove the X near Y" must not become "move X near Y" however alike they read.
INTENT_PENALTY = 0.3
# Dry runs tried before giving up (each costs a transaction on a copy of the scene).
DRY_RUNS = 3


def score(hit: Hit, fitted: Adapted, refers_back: bool, wanted: frozenset[str] = frozenset()) -> float:
    """How sure the adapted example is to do what was asked, 0..1."""
    penalty = UNFILLED_PENALTY * fitted.unfilled + UNUSED_PENALTY * fitted.unused
    penalty += STAND_IN_PENALTY * fitted.stood_in + DROPPED_PENALTY * fitted.dropped
    penalty += INTENT_PENALTY * len(wanted ^ intents(hit.example.request))
    penalty += REFERENCE_PENALTY if refers_back else 0.0
    return max(0.0, min(1.0, hit.similarity - penalty))


def _fit(hit: Hit, slots: Slots, context: PlanContext) -> Adapted:
    """The hit's calls adapted to `slots`; the request itself (a learned one) as it is."""
    if hit.similarity >= VERBATIM_SIMILARITY:
        return Adapted(list(hit.example.calls), unfilled=0, unused=0, filled=0)
    return adapt(hit.example.calls, slots, context.scene)


class RetrievalPlanner:
    """Plans by adapting the nearest examples of the world's bank."""

    name = "retrieval"

    def __init__(self, nearest: int = NEAREST, index: BankIndex | None = None) -> None:
        self.nearest = nearest
        self._index = index

    def index(self, context: PlanContext) -> BankIndex:
        return self._index if self._index is not None else bank_index(context.scene)

    def plan(self, prompt: str, context: PlanContext) -> Plan:
        """The best adapted example that a dry run accepts; PlanningError if none does."""
        started = time.perf_counter()
        hits = self.index(context).nearest(prompt, self.nearest)
        slots = read_slots(prompt, context.scene)
        refers_back = REFERENCES.search(prompt.lower()) is not None
        wanted = intents(prompt)
        ranked = sorted(
            ((score(h, fitted, refers_back, wanted), h, fitted) for h in hits for fitted in [_fit(h, slots, context)]),
            key=lambda t: -t[0],
        )
        lines = [f"slots: {', '.join(f'{k}={v}' for k, v in slots.found) or '(none)'}"]
        refusals: list[str] = []
        for confidence, hit, fitted in ranked[:DRY_RUNS]:
            refusal = context.check(fitted.calls)
            lines.append(
                f"{hit.similarity:.2f} {hit.example.request!r} -> {confidence:.2f} "
                f"(unfilled {fitted.unfilled}, unused {fitted.unused})" + (f" refused: {refusal}" if refusal else "")
            )
            if refusal is not None:
                refusals.append(refusal)
                continue
            step = TraceStep(
                level="retrieval", input=prompt, output="\n".join(lines), seconds=time.perf_counter() - started
            )
            return Plan(
                calls=fitted.calls,
                planner=self.name,
                confidence=confidence,
                prompt_version=PROMPT_VERSION,
                trace=[step],
            )
        if not ranked:
            raise PlanningError("the example bank of this world is empty")
        nearest = ranked[0][1].example.request
        raise PlanningError(
            f"no example like it fits this scene (nearest: {nearest!r}; {refusals[0] if refusals else 'no fit'})"
        )


__all__ = ["NEAREST", "RetrievalPlanner", "score"]
