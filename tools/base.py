"""The Worker tool contract: a name, a description, an argument model, a check and an apply.

A tool never edits a Scene itself: `propose` computes the WorldEdit it would make, and it is
the only method a Worker implements. The host (the registry, inside a transaction) applies the
world rules to every proposal itself: `check` and `apply` are host methods that a subclass
may not override (a plugin that does is reported, and its override is never called).
The transaction applies edits; nothing else does.
"""

from __future__ import annotations

from abc import ABC, abstractmethod
from dataclasses import dataclass, field
from typing import Annotated, Any, ClassVar, Generic, Literal, TypeVar, final

from drivetwin.tools.errors import ToolArgumentError
from drivetwin.tools.rules import check_edit
from drivetwin.worlds.catalog import nearest_categories, placeable_categories, resolve_category
from drivetwin.worlds.edits import WorldEdit
from drivetwin.worlds.scene import Scene
from pydantic import AfterValidator, BaseModel, ConfigDict, Field, ValidationError

Family = Literal["search", "add", "remove", "position", "move", "arrange", "appearance"]
FAMILIES: tuple[Family, ...] = (
    "search", "add", "remove", "position", "move", "arrange", "appearance",
)


def _canonical_category(text: str) -> str:
    name = resolve_category(text)
    if name is None:
        raise ValueError(
            f"unknown asset {text!r}; nearest: {', '.join(nearest_categories(text))}"
        )
    return name


# A catalog category; synonyms ("cones", "pylon") are accepted and become the canonical name.
CategoryName = Annotated[
    str,
    AfterValidator(_canonical_category),
    Field(json_schema_extra={"enum": placeable_categories()}),
]


class ToolArgs(BaseModel):
    """Base of every tool's argument model: unknown fields are errors, not silently dropped."""

    model_config = ConfigDict(extra="forbid")


class ToolCall(BaseModel):
    """One call of a Worker tool, as a planner produces it."""

    model_config = ConfigDict(extra="forbid")

    tool: str = Field(min_length=1, max_length=64)
    args: dict[str, Any] = Field(default_factory=dict)

    def __str__(self) -> str:
        inner = ", ".join(f"{k}={v!r}" for k, v in self.args.items())
        return f"{self.tool}({inner})"


@dataclass(frozen=True)
class ToolResult:
    """What a tool did or found: the edit it makes and a short text for the user or LLM."""

    edit: WorldEdit
    text: str
    # Where the edit happened (x, y), so that "around there" in a later turn has a referent.
    focus: tuple[float, float] | None = None
    data: dict[str, Any] = field(default_factory=dict)


ArgsT = TypeVar("ArgsT", bound=ToolArgs)


class Tool(ABC, Generic[ArgsT]):
    """A rule-based Worker. Subclasses set the class attributes and implement `propose`."""

    name: ClassVar[str]
    description: ClassVar[str]
    family: ClassVar[Family]
    Args: type[ArgsT]

    @abstractmethod
    def propose(self, args: ArgsT, scene: Scene) -> ToolResult:
        """The edit this call would make to `scene`, without checking placement rules."""

    @final
    def check(self, args: ArgsT, scene: Scene) -> None:
        """Raise a ToolError if the call cannot be applied to `scene`; change nothing."""
        self.apply(args, scene)

    @final
    def apply(self, args: ArgsT, scene: Scene) -> ToolResult:
        """The checked edit and result text; raises a ToolError and changes nothing on refusal."""
        result = self.propose(args, scene)
        check_edit(scene, result.edit)
        return result

    @final
    def parse(self, raw: dict[str, Any]) -> ArgsT:
        """Validate raw arguments against the tool's model."""
        try:
            return self.Args.model_validate(raw)
        except ValidationError as exc:
            raise ToolArgumentError.from_validation(self.name, exc) from exc

    def json_schema(self, scene: Scene | None = None) -> dict[str, Any]:
        """The tool as an LLM sees it: name, description and the JSON Schema of its arguments."""
        return {
            "name": self.name,
            "description": self.description,
            "family": self.family,
            "parameters": self.Args.model_json_schema(),
        }


HOST_METHODS = ("check", "apply", "parse")


def overridden_host_methods(tool: Tool[Any]) -> list[str]:
    """The host methods a Worker's class overrides (the host never calls those overrides)."""
    return [name for name in HOST_METHODS if getattr(type(tool), name, None) is not getattr(Tool, name)]
