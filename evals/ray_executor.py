"""The Ray executor: trials on the actors of a Ray cluster, for suites that outgrow one machine.

Needs the `ray` extra (`pip install 'drivetwin[ray]'`). With no cluster already connected it
starts a local Ray instance with `workers` CPUs; set RAY_ADDRESS to use a running cluster.
Each actor builds its planner once, like a local worker process.
"""

from __future__ import annotations

import os
from typing import Any

from drivetwin.evals.executors import Job, OnRecord, TrialWorker
from drivetwin.evals.records import TrialRecord


class RayUnavailable(RuntimeError):
    """Ray is not installed; the message names the extra that installs it."""


def run_ray(jobs: list[Job], planner_name: str, options: dict[str, Any], workers: int, on_record: OnRecord) -> None:
    """Run jobs on `workers` Ray actors and hand each record over as it arrives."""
    try:
        import ray
        from ray.util import ActorPool
    except ImportError as exc:
        raise RayUnavailable(
            "the ray executor needs Ray: pip install 'drivetwin[ray]' (or pip install 'ray>=2.30')"
        ) from exc
    started_here = not ray.is_initialized()
    if started_here:
        ray.init(
            address=os.environ.get("RAY_ADDRESS"),
            num_cpus=None if os.environ.get("RAY_ADDRESS") else max(1, workers),
            include_dashboard=False,
            log_to_driver=False,
        )
    actor_class = ray.remote(num_cpus=1)(TrialWorker)
    actors: list[Any] = [actor_class.remote(planner_name, options) for _ in range(max(1, workers))]
    pool = ActorPool(actors)
    try:
        results = pool.map_unordered(lambda actor, job: actor.run.remote(*job), list(jobs))
        for text in results:
            on_record(TrialRecord.model_validate_json(text))
    finally:
        for actor in actors:
            ray.kill(actor)
        if started_here:
            ray.shutdown()
