"""The inputs a user handles as objects: pads, soils, landers and lander scenarios.

    pad = touchdown.Pad.load("flat")              # a catalogue name, or a YAML file's path
    soil = touchdown.Soil.from_dict({...})        # a YAML file's content
    soil.zeta_N_cm3, soil.fields                  # the fields as the loader resolved them
    touchdown.drop(pad=pad, soil=soil, speed=1.0) # wherever a name or a path is taken

Each object is loaded, and so validated, by the command line's loader when it is made (a bad
field raises ValueError then, not at the first run), and its `fields` are what that loader
resolved, as the writer of the resolved file states them (a soil as `calibrate --law bekker`
writes one, a pad as the loader's pad file plus its rigid body, a lander and a scenario as
`touchdown lander --out` writes scenario_resolved.yaml): defaults filled in, a derived zeta as
its number, keys with unit suffixes. An object stands for its file (os.fspath(obj)); one made
from a dict writes it once into a private temporary directory that lives as long as the object.
Objects never change once made: their fields are read-only (setting one raises; change a copy,
copy.deepcopy(obj.fields), and build another with from_dict), and they pickle (to another
process: multiprocessing, concurrent.futures), a dict-made one with its content.
"""
import collections.abc
import copy
import json
import os
import tempfile

from . import _touchdown


class InputObject:
    """A pad, soil, lander or lander scenario, loaded (see the module's doc). Not for direct use:
    Pad, Soil, Lander, Scenario."""

    _label = ""         # "pad": the word in messages and a dict's file name
    _path_fields = ()   # dotted keys of a dict that name files, relative to the working directory

    def __init__(self, source, fields, *, document=None, scratch=None, text=None):
        set_ = object.__setattr__  # the object is read-only from outside (__setattr__)
        set_(self, "_source", source)        # the file read (for a dict: its private copy)
        set_(self, "_fields", _frozen(fields))
        set_(self, "_document", document)    # the dict it was made from, or None
        set_(self, "_scratch", scratch)      # the TemporaryDirectory holding a dict's file
        set_(self, "_text", text)            # a dict's file content, as written (what a pickle carries)

    @classmethod
    def load(cls, name_or_path):
        """The bundled input of that name, or the YAML file at that path (as the command line
        finds it)."""
        if isinstance(name_or_path, cls):
            return name_or_path
        if isinstance(name_or_path, InputObject):
            raise TypeError(f"{cls.__name__}.load: a name or a path, got a {type(name_or_path).__name__}")
        source = os.path.abspath(cls._resolve(os.fspath(name_or_path)))
        return cls(source, cls._read_fields(source))

    @classmethod
    def from_dict(cls, document, *, relative_to=None):
        """An input from a YAML file's content (e.g. yaml.safe_load of a bundled file, edited).
        Files it names by a relative path (a pad's mesh, a lander's pad, a scenario's lander) are
        relative to `relative_to` (default: the working directory); an object may stand in for
        one. A dict without `name` is named after the kind ("pad"). Errors name the dict ("pad
        dict: ...") rather than its temporary file."""
        if not isinstance(document, collections.abc.Mapping):
            raise TypeError(f"{cls.__name__}.from_dict: a dict, got {type(document).__name__}")
        from . import _yaml_text

        base = os.path.abspath(os.fspath(relative_to)) if relative_to is not None else os.getcwd()
        text = _yaml_text(cls._with_absolute_paths(_with_object_paths(document), base))
        scratch = tempfile.TemporaryDirectory(prefix="touchdown_")
        path = os.path.join(scratch.name, cls._label + ".yaml")
        with open(path, "w", encoding="utf-8") as f:
            f.write(text + "\n")
        try:
            fields = cls._read_fields(path)
        except (ValueError, OSError) as e:
            scratch.cleanup()
            raise _renamed(e, path, cls._label + " dict") from None
        return cls(path, fields, document=copy.deepcopy(dict(document)), scratch=scratch, text=text)

    @property
    def fields(self):
        """The resolved fields, read-only (a change raises TypeError; copy.deepcopy(obj.fields)
        gives plain dicts and lists to change and build another object with from_dict)."""
        return self._fields

    @property
    def name(self):
        return self._fields.get("name")

    @property
    def source(self):
        """The YAML file read: the bundled or given file, or a dict's private copy."""
        return self._source

    @property
    def document(self):
        """The dict this object was made from (None for a loaded file)."""
        return copy.deepcopy(self._document)

    def __fspath__(self):
        return self._source

    def __getattr__(self, key):
        # Only a field: private and special names are never fields (unpickling and copying probe
        # them before the object has any fields, where a lookup of self._fields would recurse).
        fields = self.__dict__.get("_fields")
        if key.startswith("_") or fields is None:
            raise AttributeError(key)
        if key in fields:
            return fields[key]
        raise AttributeError(f"{type(self).__name__} {fields.get('name')!r} has no field {key!r} "
                             f"(fields: {', '.join(fields)})")

    def __setattr__(self, key, value):
        raise AttributeError(f"{type(self).__name__} fields are read-only ({key!r}): build another with "
                             f"{type(self).__name__}.from_dict(dict(copy.deepcopy(obj.fields), {key}=...))")

    def __delattr__(self, key):
        raise AttributeError(f"{type(self).__name__} fields are read-only ({key!r})")

    def __dir__(self):
        return sorted(set(super().__dir__()) | set(self._fields))

    def __eq__(self, other):
        return type(other) is type(self) and other._fields == self._fields

    __hash__ = None  # compared by value, like the dicts of its fields

    # Never changed once made, so a copy is the object itself (a dict-made one's file stays with it).
    def __copy__(self):
        return self

    def __deepcopy__(self, memo):
        return self

    # To another process: a loaded file's object as its path and fields (read again there only
    # for its file: the fields are kept as resolved here); a dict-made one as its content, written
    # into a private directory of the receiving process, and its dict.
    def __reduce__(self):
        if self._text is not None:
            return (_from_text, (type(self), self._text, self._document))
        return (_from_resolved, (type(self), self._source, _thawed(self._fields)))

    def __repr__(self):
        shown = [f"{key}={value!r}" for key, value in self._fields.items()
                 if key not in ("schema_version", "name", "source") and not isinstance(value, (dict, list))]
        nested = [key for key, value in self._fields.items() if isinstance(value, (dict, list))]
        origin = "dict" if self._document is not None else self._source
        parts = [repr(self.name)] + shown + [f"{key}=..." for key in nested] + [f"source={origin!r}"]
        return f"{type(self).__name__}({', '.join(parts)})"

    # What a kind reads: the file a name or path resolves to, and the resolved fields of a file.
    @classmethod
    def _resolve(cls, name_or_path):
        raise NotImplementedError

    @classmethod
    def _read_fields(cls, path):
        raise NotImplementedError

    @classmethod
    def _with_absolute_paths(cls, document, base):
        """The dict with the files it names by relative path (cls._path_fields) made absolute
        against `base`; a name (no '/', no .yaml ending) stays a catalogue name."""
        document = dict(document)
        for dotted in cls._path_fields:
            *parents, key = dotted.split(".")
            holder = document
            for parent in parents:
                if not isinstance(holder.get(parent), collections.abc.Mapping):
                    holder = None
                    break
                holder[parent] = dict(holder[parent])
                holder = holder[parent]
            if holder is not None and isinstance(holder.get(key), (str, os.PathLike)):
                path = os.fspath(holder[key])
                if (key == "file" or _reads_as_path(path)) and not os.path.isabs(path):
                    holder[key] = os.path.join(base, path)
        return document


class Pad(InputObject):
    """A pad (data/pads: flat, c4, curved, hex). fields: the pad file as the loader read it
    (kind, mass_kg or density_kg_m3, profile or mesh with its file's absolute path,
    reference_point_mm, ...) and `body`, the rigid body it built: mass_kg, center_of_mass_mm and
    inertia_kg_m2 (3 x 3, about the centre of mass, row by row) in the pad frame,
    lowest_point_mm, triangles, rim_segments."""

    _label = "pad"
    _path_fields = ("mesh.file",)

    @classmethod
    def _resolve(cls, name_or_path):
        return _touchdown.catalog_file("pads", name_or_path)

    @classmethod
    def _read_fields(cls, path):
        with tempfile.TemporaryDirectory(prefix="touchdown_") as scratch:
            return json.loads(_touchdown.resolved_pad(path, os.path.join(scratch, "pad.yaml")))


class Soil(InputObject):
    """A soil (data/soils: fjs1_lp, fjs1_cp, ... and the Bekker soils). fields: the soil as the
    simulation uses it, written as a soil file (zeta_N_cm3 a number even where the file derives
    it, atmosphere, the number fields, law, bekker, dynamic_term)."""

    _label = "soil"

    @classmethod
    def _resolve(cls, name_or_path):
        return _touchdown.catalog_file("soils", name_or_path)

    @classmethod
    def _read_fields(cls, path):
        return json.loads(_touchdown.resolved_soil(path))


class Scenario(InputObject):
    """A lander scenario (data/scenarios: lander_case_A, ...; `touchdown lander`'s input), passed
    to touchdown.lander or simulate_lander. fields: scenario_resolved.yaml as `touchdown lander
    --out` writes it (lander with masses, pad and legs; ground with its soils and zeta at the
    scenario's gravity; initial with the release position; simulation), files named as from the
    working directory ("$TOUCHDOWN_DATA_DIR/..." for bundled ones)."""

    _label = "scenario"
    _path_fields = ("lander",)

    @classmethod
    def _resolve(cls, name_or_path):
        return _touchdown.lander_scenario_file(name_or_path)

    @classmethod
    def _read_fields(cls, path):
        return _resolved_scenario(path)


class Lander(InputObject):
    """A lander (data/landers: sutoh2017_lander, ...), the `lander:` of a scenario. fields: the
    `lander` block `touchdown lander --out` writes into scenario_resolved.yaml: total_mass_kg,
    body_mass_kg (the total less the pads), cog_height_mm, body_inertia_kg_m2 (3 x 3), the pad
    (name, file, mass_kg, ...) and each leg's joint and hip positions from the body's centre of
    mass, absorbers and cone limits."""

    _label = "lander"
    _path_fields = ("pad",)

    @classmethod
    def _resolve(cls, name_or_path):
        return _touchdown.catalog_file("landers", name_or_path)

    @classmethod
    def _read_fields(cls, path):
        # The lander alone (its pad placed, its body's mass and centre of mass derived): the
        # `lander` block a scenario's resolved copy states, without a ground or a release.
        with tempfile.TemporaryDirectory(prefix="touchdown_") as scratch:
            return json.loads(_touchdown.resolved_lander(path, os.path.join(scratch, "lander_resolved.yaml"),
                                                         os.getcwd()))


class _FrozenDict(dict):
    """A resolved object's fields: a dict that refuses changes (a change to a copy used to do
    nothing, silently). copy.deepcopy gives plain dicts and lists back."""

    def _refuse(self, *args, **kwargs):
        raise TypeError("an object's fields are read-only: change copy.deepcopy(obj.fields) and build another "
                        "object with from_dict")

    __setitem__ = __delitem__ = __ior__ = clear = pop = popitem = setdefault = update = _refuse

    def __deepcopy__(self, memo):
        return _thawed(self)

    def __copy__(self):
        return dict(self)

    def __reduce__(self):
        return (dict, (_thawed(self),))


class _FrozenList(list):
    """A list among an object's fields: read-only, as _FrozenDict."""

    _refuse = _FrozenDict._refuse
    __setitem__ = __delitem__ = __iadd__ = __imul__ = append = clear = extend = insert = pop = remove = \
        reverse = sort = _refuse

    def __deepcopy__(self, memo):
        return _thawed(self)

    def __copy__(self):
        return list(self)

    def __reduce__(self):
        return (list, (_thawed(self),))


def _frozen(value):
    if isinstance(value, collections.abc.Mapping):
        return _FrozenDict({k: _frozen(v) for k, v in value.items()})
    if isinstance(value, list):
        return _FrozenList(_frozen(v) for v in value)
    return value


def _thawed(value):
    if isinstance(value, collections.abc.Mapping):
        return {k: _thawed(v) for k, v in value.items()}
    if isinstance(value, list):
        return [_thawed(v) for v in value]
    return value


def _from_resolved(cls, source, fields):
    return cls(source, fields)


def _from_text(cls, text, document):
    """A dict-made object again, from the file content it wrote (paths in it already absolute)."""
    scratch = tempfile.TemporaryDirectory(prefix="touchdown_")
    path = os.path.join(scratch.name, cls._label + ".yaml")
    with open(path, "w", encoding="utf-8") as f:
        f.write(text + "\n")
    return cls(path, cls._read_fields(path), document=document, scratch=scratch, text=text)


def _resolved_scenario(path):
    with tempfile.TemporaryDirectory(prefix="touchdown_") as scratch:
        return json.loads(_touchdown.resolved_scenario(path, os.path.join(scratch, "scenario_resolved.yaml"),
                                                       os.getcwd()))


def _reads_as_path(text):
    """As the loaders tell a path from a catalogue name (drop_tests/catalog/catalog.h)."""
    return "/" in text or text.endswith((".yaml", ".yml")) or os.sep in text


def _with_object_paths(value):
    """A dict, list or value with every InputObject in it replaced by its file's path."""
    if isinstance(value, InputObject):
        return os.fspath(value)
    if isinstance(value, collections.abc.Mapping):
        return {k: _with_object_paths(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_with_object_paths(v) for v in value]
    return value


def _renamed(error, path, name):
    """The same exception with `path` in its message shown as `name`."""
    message = str(error)
    if path not in message:
        return error
    renamed = type(error)(message.replace(path, name))
    if isinstance(error, OSError):
        renamed.errno = error.errno
    return renamed
