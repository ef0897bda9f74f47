"""Immutable values written out instead of frozen dataclasses, for the start's sake: a frozen
dataclass compiles six methods when its module is imported (``slots=True`` builds its class
twice too), at every start (benchmarks/README.md, "startup").
A :class:`Frozen` subclass names the fields it is compared, hashed and shown by and sets
them once (:meth:`Frozen._assign`); it behaves as a frozen dataclass does (``__init__``
takes the fields by name, so :meth:`Frozen.replace`, pickling and copying remake it)."""

from __future__ import annotations

from dataclasses import FrozenInstanceError
from typing import TYPE_CHECKING, Any, ClassVar, TypeVar

if TYPE_CHECKING:
    from typing_extensions import Self

_F = TypeVar("_F", bound="Frozen")


class Frozen:
    """Equal (to the same class only) and hashed by the values of :attr:`_FIELDS`, shown as
    ``Name(field=value, ...)``, and never changed once made (:class:`FrozenInstanceError`)."""

    __slots__ = ()
    _FIELDS: ClassVar[tuple[str, ...]] = ()

    def _assign(self, **values: Any) -> None:
        """Set the attributes, once, as ``__init__`` makes the value."""
        for name, value in values.items():
            object.__setattr__(self, name, value)

    def replace(self, **changes: Any) -> Self:
        """A copy with ``changes`` made, as :func:`dataclasses.replace` makes one: the
        class's ``__init__`` takes every field of :attr:`_FIELDS` by name."""
        values = {name: getattr(self, name) for name in self._FIELDS}
        values.update(changes)
        return type(self)(**values)

    def __reduce__(self) -> tuple[Any, ...]:
        """Pickled and copied as made: by ``__init__`` with the fields by name."""
        return _remake, (type(self), {name: getattr(self, name) for name in self._FIELDS})

    def _values(self) -> tuple[object, ...]:
        return tuple(getattr(self, name) for name in self._FIELDS)

    def __setattr__(self, name: str, value: object) -> None:
        raise FrozenInstanceError(f"cannot assign to field {name!r}")

    def __delattr__(self, name: str) -> None:
        raise FrozenInstanceError(f"cannot delete field {name!r}")

    def __eq__(self, other: object) -> bool:
        if other.__class__ is not self.__class__:
            return NotImplemented
        assert isinstance(other, Frozen)
        return self._values() == other._values()

    def __hash__(self) -> int:
        return hash(self._values())

    def __repr__(self) -> str:
        fields = ", ".join(f"{name}={getattr(self, name)!r}" for name in self._FIELDS)
        return f"{type(self).__name__}({fields})"


def _remake(cls: type[_F], values: dict[str, Any]) -> _F:
    return cls(**values)
