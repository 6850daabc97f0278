"""Typed refusals of Worker tools: each message says what was wrong and what is allowed."""

from __future__ import annotations

from typing import ClassVar

from pydantic import ValidationError


class ToolError(Exception):
    """Something a tool refused; the message says what was wrong and what is allowed."""

    kind: ClassVar[str] = "error"


class UnknownToolError(ToolError):
    """A call named a tool the registry does not have."""

    kind = "unknown_tool"


class ToolArgumentError(ToolError):
    """A call's arguments do not match the tool's schema."""

    kind = "arguments"

    @classmethod
    def from_validation(cls, tool: str, exc: ValidationError) -> ToolArgumentError:
        details = "; ".join(
            f"{'.'.join(str(p) for p in err['loc']) or 'args'}: {err['msg']}" for err in exc.errors()
        )
        return cls(
            f"{exc.error_count()} validation error(s) for {tool}: {details}. "
            "Fix the errors and try again."
        )


class NotFoundError(ToolError):
    """A call referred to an asset, landmark or lane that does not exist."""

    kind = "not_found"


class RuleViolation(ToolError):
    """An edit that breaks a placement rule (bounds, building, overlap, surface, limits)."""

    kind = "rule"

    def __init__(self, rule: str, message: str) -> None:
        self.rule = rule
        super().__init__(message)


class PluginError(ToolError):
    """A plugin's code failed, hung, exited or broke the contract; the message names the plugin."""

    kind = "plugin"
