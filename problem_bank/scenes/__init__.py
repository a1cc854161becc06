"""The scene families of the bank, one small module each; `SCENES` lists them in lecture order."""

from . import hoop, wedge

SCENES = tuple(module.SCENE for module in (wedge, hoop))
