#!/usr/bin/env python3
"""Writes the device descriptions beside this file (hub, printer, printer2,
raw .umockdev): run it after changing a descriptor below."""
import os
import struct

HERE = os.path.dirname(os.path.abspath(__file__))

def dev_desc(cls, vid, pid, bcd, strings=(1,2,3), mps=64):
    return struct.pack('<BBHBBBBHHHBBBB', 18, 1, 0x200, cls, 0, 0, mps, vid, pid, bcd, *strings, 1)
def cfg(ifaces, attr=0xC0, power=0x32):
    body = b''.join(ifaces)
    return struct.pack('<BBHBBBBB', 9, 2, 9 + len(body), len(ifaces) and 1, 1, 0, attr, power) + body
def iface(num, cls, sub, proto, eps):
    return struct.pack('<BBBBBBBBB', 9, 4, num, 0, len(eps), cls, sub, proto, 0) + b''.join(eps)
def ep(addr, attr, mps, interval=0):
    return struct.pack('<BBBBHB', 7, 5, addr, attr, mps, interval)

def write(name, comment, sysname, devnum, d, attrs, cls_env):
    hx = d.hex().upper()
    with open(os.path.join(HERE, name), 'w') as f:
        f.write('P: /devices/pci0000:00/0000:00:14.0/%s\n' % sysname)
        f.write('N: bus/usb/001/%03d=%s\n' % (devnum, hx))
        vid, pid = struct.unpack('<HH', d[8:12])
        env = [('BUSNUM', '001'), ('DEVNAME', '/dev/bus/usb/001/%03d' % devnum), ('DEVNUM', '%03d' % devnum),
               ('DEVTYPE', 'usb_device'), ('DRIVER', 'usb'), ('MAJOR', '189'), ('MINOR', str(devnum - 1)),
               ('PRODUCT', '%x/%x/%x' % (vid, pid, struct.unpack('<H', d[12:14])[0])), ('SUBSYSTEM', 'usb'), ('TYPE', cls_env)]
        for k, v in env:
            f.write('E: %s=%s\n' % (k, v))
        base = [('bConfigurationValue', '1'), ('bDeviceClass', '%02x' % d[4]), ('bNumConfigurations', '1'),
                ('busnum', '1')]
        for k, v in base:
            f.write('A: %s=%s\n' % (k, v))
        f.write('H: descriptors=%s\n' % hx)
        more = [('dev', '189:%d' % (devnum - 1)), ('devnum', str(devnum)), ('idProduct', '%04x' % pid),
                ('idVendor', '%04x' % vid)] + attrs + [('speed', '480')]
        for k, v in more:
            f.write('A: %s=%s\n' % (k, v))
        f.write('\n')

hub = dev_desc(9, 0x1d6b, 2, 0x0606, (3, 2, 1)) + cfg([iface(0, 9, 0, 0, [ep(0x81, 3, 4, 12)])], 0xE0, 0)
printer = dev_desc(0, 0x0bad, 0x1001, 0x0100) + cfg([iface(0, 7, 1, 2, [ep(0x01, 2, 512), ep(0x82, 2, 512)])])
raw = dev_desc(0xff, 0x0bad, 0x2002, 0x0100) + cfg([iface(0, 0xff, 0, 0, [ep(0x02, 2, 512)])], 0x80)

write('hub.umockdev', ['The root hub of bus 1 (a hub: quiltc devices leaves it out).'],
      'usb1', 1, hub, [('manufacturer', 'Linux 6.1.0 xhci-hcd'), ('product', 'xHCI Host Controller')], '9/0/1')
write('printer.umockdev',
      ['A USB printer-class machine, 0bad:1001 at bus 1 port 2: interface 0 is class 7,',
       'subclass 1, protocol 2 (bidirectional), bulk OUT 0x01 and bulk IN 0x82, 512-byte packets.'],
      'usb1/1-2', 2, printer, [('manufacturer', 'Quilt Test'), ('product', 'Long Arm 9'), ('serial', 'QT0001')], '0/0/0')
write('printer2.umockdev',
      ['A second machine with the same ids as printer.umockdev, at bus 1 port 4.'],
      'usb1/1-4', 4, printer, [('manufacturer', 'Quilt Test'), ('product', 'Long Arm 9'), ('serial', 'QT0002')], '0/0/0')
write('raw.umockdev',
      ['A vendor-specific machine, 0bad:2002 at bus 1 port 3: one interface of class 0xff',
       'with a single bulk OUT endpoint 0x02 (512-byte packets), no IN endpoint.'],
      'usb1/1-3', 3, raw, [('manufacturer', 'Quilt Test'), ('product', 'Raw Plotter')], '255/0/0')
