"""The scene file as TOML text. Blender's own Python (blender.org builds bundle one) has no TOML
writer, and a scene needs only tables, arrays of tables, strings, numbers and lists of numbers."""

import math


def _value(value):
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):
        if not math.isfinite(value):
            raise ValueError(f"modeflow scene: {value} is not a finite number")
        return repr(value)
    if isinstance(value, str):
        return '"' + value.replace("\\", "\\\\").replace('"', '\\"') + '"'
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(_value(v) for v in value) + "]"
    raise TypeError(f"modeflow scene: cannot write {type(value).__name__} as TOML")


def _table(lines, header, table):
    lines.append(header)
    for key, value in table.items():
        lines.append(f"{key} = {_value(value)}")
    lines.append("")


def scene_toml(scene):
    """`scene`: {section: {key: value}} for tables and {section: [{key: value}, ...]} for arrays
    of tables ([[obstacle]], [[source]])."""
    lines = []
    for section, content in scene.items():
        if isinstance(content, dict):
            _table(lines, f"[{section}]", content)
        else:
            for table in content:
                _table(lines, f"[[{section}]]", table)
    return "\n".join(lines)
