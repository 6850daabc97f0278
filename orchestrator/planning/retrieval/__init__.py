"""Retrieval: a generated example bank per world, nearest examples by MiniLM, and a planner
that adapts the nearest examples' calls to the request's own names and numbers.

    index = bank_index(scene)                    # built and cached once per world
    hits = index.nearest("put two benches by the library", k=4)
    plan = RetrievalPlanner().plan(prompt, context)
    learn(scene, prompt, calls)                  # what a person accepted, used from now on
"""

from drivetwin.orchestrator.planning.retrieval.bank import Example, learn, learn_accepted, user_bank, world_bank
from drivetwin.orchestrator.planning.retrieval.index import BankIndex, Hit, bank_index, warm_bank
from drivetwin.orchestrator.planning.retrieval.planner import RetrievalPlanner

__all__ = [
    "BankIndex",
    "Example",
    "Hit",
    "RetrievalPlanner",
    "bank_index",
    "learn",
    "learn_accepted",
    "user_bank",
    "warm_bank",
    "world_bank",
]
