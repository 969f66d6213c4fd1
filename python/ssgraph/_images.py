"""Images between numpy and the library. ssgraph's images are planar float32 (channel 0's
rows, then channel 1's, ...); numpy's are H x W (one channel) or H x W x C, interleaved.

Into the library: one copy, from the array into a new planar image (the array must be
float32 and C-contiguous: nothing is converted behind the caller's back). Out of it: the
library's image is viewed in place and interleaved into a new array (one copy), then freed;
the array belongs to the caller and no later run changes it."""
import os
from typing import Optional

import numpy as np

from . import _args
from ._errors import new_diags, raise_for
from ._lock import locked
from ._ssgraph import ffi, lib


def check_array(array, what: str) -> np.ndarray:
    """The array as the library takes it, or TypeError / ValueError saying why not."""
    if not isinstance(array, np.ndarray):
        raise TypeError("%s: expected a numpy.ndarray, got %s" % (what, type(array).__name__))
    if array.dtype != np.float32:
        raise TypeError("%s: expected dtype float32, got %s (convert it: "
                        "a.astype(numpy.float32))" % (what, array.dtype))
    if array.ndim not in (2, 3) or (array.ndim == 3 and not 1 <= array.shape[2] <= 4):
        raise ValueError("%s: expected shape (H, W) or (H, W, C) with C 1..4, got %s"
                         % (what, array.shape))
    if array.shape[0] < 1 or array.shape[1] < 1:
        raise ValueError("%s: an empty image, shape %s" % (what, array.shape))
    if not array.flags["C_CONTIGUOUS"]:
        raise ValueError("%s: the array is not C-contiguous (a slice or a transpose): pass "
                         "numpy.ascontiguousarray(a)" % what)
    return array


def to_library(array: np.ndarray, what: str):
    """A new struct ssg_image (freed with the returned owner) holding the array's pixels."""
    array = check_array(array, what)
    h, w = array.shape[:2]
    c = 1 if array.ndim == 2 else array.shape[2]
    image = lib.ssg_image_create(w, h, c)
    if image == ffi.NULL:
        raise MemoryError("%s: cannot allocate a %dx%d image of %d channels" % (what, w, h, c))
    owner = ffi.gc(image, _destroy)
    planes = np.frombuffer(ffi.buffer(image.data, w * h * c * 4), np.float32).reshape(c, h, w)
    planes[...] = array.reshape(h, w, c).transpose(2, 0, 1)
    return owner


def _destroy(image) -> None:
    holder = ffi.new("struct ssg_image **", image)
    lib.ssg_image_destroy(holder)


def from_library(image, planar: bool = False) -> np.ndarray:
    """A new array of the image's pixels (H x W for one channel, else H x W x C; planar:
    C x H x W), then the image is freed."""
    try:
        w, h, c = image.width, image.height, image.channels
        planes = np.frombuffer(ffi.buffer(image.data, w * h * c * 4), np.float32)
        planes = planes.reshape(c, h, w)
        if planar:
            return planes.copy()
        if c == 1:
            return planes[0].copy()
        return np.ascontiguousarray(planes.transpose(1, 2, 0))
    finally:
        _destroy(image)


def read_image(path: str, layer: Optional[str] = None) -> np.ndarray:
    """Reads an image file (EXR, PNG, HDR, ... through OpenImageIO) as float32: H x W for
    one channel, else H x W x C. `layer` picks an EXR layer by name ("ao" reads the
    channels "ao.*"); None reads the unnamed channels (or all when there are none)."""
    raw = _args.c_path(path, "path")
    name = _args.c_text(layer, "layer") if layer else ffi.NULL
    out = ffi.new("struct ssg_image **")
    diags = new_diags()
    with locked():
        err = lib.ssg_image_read(raw, name, out, diags)
    raise_for(err, diags, "reading " + os.fsdecode(raw))
    return from_library(out[0])


def write_image(path: str, array: np.ndarray) -> None:
    """Writes a float32 array as a 32-bit float EXR (1 channel: Y; 3: R, G, B; 4: RGBA),
    through a temporary file renamed into place."""
    raw = _args.c_path(path, "path")
    image = to_library(array, "write_image")
    diags = new_diags()
    with locked():
        err = lib.ssg_image_write(raw, image, diags)
    raise_for(err, diags, "writing " + os.fsdecode(raw))
