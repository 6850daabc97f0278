"""The words that say whether a request adds or takes away: one small general vocabulary, read
by the plan-versus-request check (request.py) and by the rule planner, so that the two never
disagree on which way a request points ("take it out", "without the bin", "no hydrant").
"""

from __future__ import annotations

import re

REMOVE_WORDS = re.compile(
    r"\b(remove|delete|get rid of|take (?:(?:it|them|that|those|this|these) )?(away|out)|clear (away|out|the)|no longer|don'?t want|do not want"
    r"|not (want|have|need|keep)|no more|without|fewer|less|lose|eliminate|erase|discard|scrap)\b"
    r"|^no (?=[a-z])"  # "no hydrant": a request that opens with "no" and a thing wants it gone
)
ADD_WORDS = re.compile(r"\b(add|more|another|extra|busier|fuller|create|spawn|insert|put|place|bring in|new)\b")


__all__ = ["ADD_WORDS", "REMOVE_WORDS"]
