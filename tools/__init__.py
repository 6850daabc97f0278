"""Worker tools: the registry, the tool contract and the built-in Workers."""

from drivetwin.tools.base import FAMILIES, CategoryName, Family, Tool, ToolArgs, ToolCall, ToolResult
from drivetwin.tools.errors import (
    NotFoundError,
    RuleViolation,
    ToolArgumentError,
    ToolError,
    UnknownToolError,
)
from drivetwin.tools.locate import Location
from drivetwin.tools.move import BehaviourSpec
from drivetwin.tools.registry import ENTRY_POINT_GROUP, PluginProblem, ToolRegistry, builtin_tools

__all__ = [
    "ENTRY_POINT_GROUP",
    "FAMILIES",
    "BehaviourSpec",
    "CategoryName",
    "Family",
    "Location",
    "NotFoundError",
    "PluginProblem",
    "RuleViolation",
    "Tool",
    "ToolArgs",
    "ToolArgumentError",
    "ToolCall",
    "ToolError",
    "ToolRegistry",
    "ToolResult",
    "UnknownToolError",
    "builtin_tools",
]
