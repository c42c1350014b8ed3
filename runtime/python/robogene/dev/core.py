# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The C++ device layer, bound in robogene._core: Property, DriverFactory, PolyDriver, the
generated interfaces (IEncoders, IPositionControl...) and the network servers. One factory serves
both languages: PolyDriver opens the C++ drivers (test_motor, fake_grabber, the servers and
the remote clients), and a Python device added to the factory is opened, viewed and served by
C++ code like a C++ one (docs/devices.md, "Devices written in Python")::

    from robogene.dev.core import DeviceDriver, DriverFactory, IEncoders, PolyDriver, Property

    class Counter(DeviceDriver, IEncoders):
        def open(self, config): self.axes = config.get_int("axes", 1, 1, 64); return True
        def close(self): return True
        def getAxes(self): return self.axes
        ...

    DriverFactory.instance().add("counter", "counts", Counter)
    with PolyDriver(Property.from_command_line(["--device", "controlBoard_nws_yarp",
                                                "--subdevice", "counter", "--name", "/counter"])):
        ...  # served by the C++ server

A Python device derives from DeviceDriver (this module's) and from the interfaces it
implements; each method returns what the C++ interface's out-parameters carry (None when it
cannot answer), a command returns a bool. A method that raises, called by C++, is reported
through sys.unraisablehook and answers False, as a failing C++ device does."""
from __future__ import annotations

from .. import _core
from .._core import (  # noqa: F401  (re-exported API)
    CameraFeature,
    ConfigError,
    ControlboardClient,
    ControlboardNws,
    ControlboardServer,
    ControlMode,
    DriverFactory,
    FeatureMode,
    GrabberClient,
    GrabberNws,
    GrabberServer,
    IControlMode,
    IEncoders,
    IFrameGrabberControls,
    IFrameGrabberImage,
    ImageError,
    ImageRgb,
    INetworkWrapper,
    IPidControl,
    IPositionControl,
    ISimulationClock,
    ITorqueControl,
    IVelocityControl,
    Pid,
    PidType,
    PolyDriver,
    Property,
    RemoteGrabber,
    Searchable,
    decode_image,
    encode_image,
    encode_joint_data,
    wrapper_for,
)

INTERFACES = (IControlMode, IEncoders, IFrameGrabberControls, IFrameGrabberImage, IPidControl,
              IPositionControl, ITorqueControl, IVelocityControl)


class DeviceDriver(_core.DeviceDriver):
    """The base of a device written in Python. Its __init__ sets up every bound base the class
    derives from (DeviceDriver and each interface): a subclass that defines __init__ calls
    super().__init__(). PolyDriver.view(DeviceDriver) gives the device, C++ or Python."""

    _views_as_device_driver = True  # read by PolyDriver.view, in this class's own __dict__ only

    def __init__(self) -> None:
        for base in type(self).__mro__:
            if isinstance(base, type(_core.DeviceDriver)) and "__init__" in vars(base) \
                    and base.__module__ == _core.__name__:
                base.__init__(self)


__all__ = ["CameraFeature", "ConfigError", "ControlMode", "ControlboardClient", "ControlboardNws",
           "ControlboardServer", "DeviceDriver", "DriverFactory", "FeatureMode", "GrabberClient", "GrabberNws",
           "GrabberServer", "IControlMode", "IEncoders", "IFrameGrabberControls", "IFrameGrabberImage",
           "INTERFACES", "INetworkWrapper", "IPidControl", "IPositionControl", "ISimulationClock", "ITorqueControl",
           "IVelocityControl", "ImageError", "ImageRgb", "Pid", "PidType", "PolyDriver", "Property", "RemoteGrabber", "Searchable",
           "decode_image", "encode_image", "encode_joint_data", "wrapper_for"]
