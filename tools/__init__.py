"""Worker tools, and the plugin API: everything a plugin's Worker may import is named here.

A plugin imports only from `drivetwin.tools` (see docs/plugins.md); the modules behind these
names may move between releases, these names stay.

- the Worker contract: Tool, ToolArgs, ToolResult, ToolCall, Family, FAMILIES, CategoryName
- what a Worker proposes: WorldEdit and its operations (AddAsset, RemoveAsset, UpdateAsset,
  SetEnvironment, SetStoryboard), built from the Scene it is handed (Scene, AssetInstance, Pose)
- helpers a Worker needs: new_asset (a fresh asset with a free id), lane_at,
  nearest_on_polyline, point_along (positions along lanes), Location, BehaviourSpec
- refusals a Worker raises: ToolError, NotFoundError, RuleViolation, ToolArgumentError
- the registry and the plugin loader: ToolRegistry, builtin_tools, PluginProblem, the group
  names (TOOLS_GROUP ... COMMANDS_GROUP) and load_group
"""

from drivetwin.tools.add import new_asset
from drivetwin.tools.base import FAMILIES, CategoryName, Family, Tool, ToolArgs, ToolCall, ToolResult
from drivetwin.tools.errors import (
    NotFoundError,
    PluginError,
    RuleViolation,
    ToolArgumentError,
    ToolError,
    UnknownToolError,
)
from drivetwin.tools.locate import Location
from drivetwin.tools.move import BehaviourSpec
from drivetwin.tools.plugins import (
    BACKENDS_GROUP,
    COMMANDS_GROUP,
    GROUPS,
    PLANNERS_GROUP,
    TOOLS_GROUP,
    WORLDS_GROUP,
    LoadedPlugin,
    PluginGroup,
    PluginProblem,
    load_group,
)
from drivetwin.tools.registry import ToolRegistry, builtin_tools
from drivetwin.worlds.edits import AddAsset, RemoveAsset, SetEnvironment, SetStoryboard, UpdateAsset, WorldEdit
from drivetwin.worlds.scene import AssetInstance, Pose, Scene
from drivetwin.worlds.surface import lane_at, nearest_on_polyline, point_along

__all__ = [
    "BACKENDS_GROUP",
    "COMMANDS_GROUP",
    "FAMILIES",
    "GROUPS",
    "PLANNERS_GROUP",
    "TOOLS_GROUP",
    "WORLDS_GROUP",
    "AddAsset",
    "AssetInstance",
    "BehaviourSpec",
    "CategoryName",
    "Family",
    "LoadedPlugin",
    "Location",
    "NotFoundError",
    "PluginError",
    "PluginGroup",
    "PluginProblem",
    "Pose",
    "RemoveAsset",
    "RuleViolation",
    "Scene",
    "SetEnvironment",
    "SetStoryboard",
    "Tool",
    "ToolArgs",
    "ToolArgumentError",
    "ToolCall",
    "ToolError",
    "ToolRegistry",
    "ToolResult",
    "UnknownToolError",
    "UpdateAsset",
    "WorldEdit",
    "builtin_tools",
    "lane_at",
    "load_group",
    "nearest_on_polyline",
    "new_asset",
    "point_along",
]
