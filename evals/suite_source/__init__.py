"""The development suites as readable case lists; `build.py` writes evals/suites/full.jsonl and smoke.jsonl."""
