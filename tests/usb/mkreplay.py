#!/usr/bin/env python3
"""Turns a USB scenario (tests/usb/*.urbs) into what umockdev-run replays:
a usbmon capture (pcap, link type 220 DLT_USB_LINUX_MMAPPED: in-order, bulk
OUT data compared, control replies supported) or an ioctl tree script (bulk
only: each URB's data compared, no control replies).

usage: mkreplay.py pcap|ioctl SCENARIO OUT [NAME=VALUE...]

A scenario has one operation a line; $NAME is replaced by the NAME=VALUE
arguments, '#' starts a comment:
  devid TEXT...                 printer GET_DEVICE_ID answered with TEXT
  status HEX                    printer GET_PORT_STATUS answered with byte HEX
  file EP PATH CHUNK [FROM [TO]] bulk OUT of PATH[FROM:TO] in CHUNK-byte
                                URBs (chunks counted from FROM), all accepted
  send EP PATH OFFSET LEN [STATUS [ACTUAL]]
                                one bulk OUT URB of PATH[OFFSET:OFFSET+LEN]
                                completing with errno STATUS (0, -32 stall,
                                -108 or -19 device gone) after ACTUAL bytes
The device is bus 1, the address given as DEV=N (default 2). A capture
that ends while the program still sends makes each later transfer time out.
"""
import struct
import sys

USB_DEVICE_ID_LEN = 1023  # wLength of GET_DEVICE_ID, as quiltc asks


def parse(path, env):
    ops = []
    for raw in open(path, encoding='utf-8'):
        line = raw.split('#', 1)[0].strip()
        for k, v in env.items():
            line = line.replace('$' + k, v)
        if line.startswith('devid '):
            ops.append(['devid', line[6:].strip()])
        elif line:
            ops.append(line.split())
    return ops


def urbs(ops):
    """(kind, fields) per URB: ('ctrl', setup, reply) or ('bulk', ep, data, status, actual)."""
    out = []
    for op in ops:
        name, a = op[0], op[1:]
        if name == 'devid':
            text = a[0].encode('ascii')
            reply = struct.pack('>H', len(text) + 2) + text
            # a device sends at most the wLength asked for, whatever its ID's
            # length prefix says (a longer reply corrupts umockdev's heap)
            reply = reply[:USB_DEVICE_ID_LEN]
            setup = struct.pack('<BBHHH', 0xA1, 0, 0, 0, USB_DEVICE_ID_LEN)
            out.append(('ctrl', setup, reply))
        elif name == 'status':
            setup = struct.pack('<BBHHH', 0xA1, 1, 0, 0, 1)
            out.append(('ctrl', setup, bytes([int(a[0], 16)])))
        elif name == 'file':
            ep, data, chunk = int(a[0], 16), open(a[1], 'rb').read(), int(a[2])
            lo = int(a[3]) if len(a) > 3 else 0
            hi = int(a[4]) if len(a) > 4 else len(data)
            for off in range(lo, hi, chunk):
                piece = data[off:min(off + chunk, hi)]
                out.append(('bulk', ep, piece, 0, len(piece)))
        elif name == 'send':
            ep, data = int(a[0], 16), open(a[1], 'rb').read()
            off, ln = int(a[2]), int(a[3])
            piece = data[off:off + ln]
            status = int(a[4]) if len(a) > 4 else 0
            actual = int(a[5]) if len(a) > 5 else (len(piece) if status == 0 else 0)
            out.append(('bulk', ep, piece, status, actual))
        else:
            sys.exit('mkreplay: unknown operation ' + name)
    return out


def write_pcap(items, out, dev):
    # usbmon's 64-byte mmapped header: id, type 'S'/'C', transfer type,
    # endpoint, device, bus, setup flag, data flag, seconds, microseconds,
    # status, urb length, captured length, setup bytes, interval,
    # start frame, transfer flags, iso descriptors.
    pkts, t, urb = [], 0, 0xffff880000001000

    def ev(kind, xfer, ep, status, length, data, setup=None, dflag=None):
        if dflag is None:
            dflag = 0 if data else ord('<' if ep & 0x80 else '>')
        hdr = struct.pack('<QBBBBHBBqiiII8siiII', urb, ord(kind), xfer, ep, dev, 1,
                          0 if setup is not None else ord('-'), dflag, t // 1000000,
                          t % 1000000, status, length, len(data),
                          setup if setup is not None else bytes(8), 0, 0, 0, 0)
        pkts.append((t, hdr + data))

    for item in items:
        urb += 0x40
        if item[0] == 'ctrl':
            setup, reply = item[1], item[2]
            ev('S', 2, 0x80, -115, struct.unpack('<H', setup[6:])[0], b'', setup, ord('<'))
            t += 1000
            ev('C', 2, 0x80, 0, len(reply), reply)
        else:
            ep, data, status, actual = item[1:]
            ev('S', 3, ep, -115, len(data), data)
            t += 1000
            ev('C', 3, ep, status, actual, b'')
        t += 1000
    with open(out, 'wb') as f:
        f.write(struct.pack('<IHHiIII', 0xa1b2c3d4, 2, 4, 0, 0, 262144, 220))
        for ts, p in pkts:
            f.write(struct.pack('<IIII', ts // 1000000, ts % 1000000, len(p), len(p)))
            f.write(p)


def write_ioctl(items, out, dev):
    # USBDEVFS_REAPURBNDELAY ret type endpoint status flags buffer_length
    # actual_length error_count data: REAPURB would make libusb spin.
    with open(out, 'w', encoding='ascii') as f:
        f.write('@DEV /dev/bus/usb/001/%03d\n' % dev)
        for item in items:
            if item[0] != 'bulk':
                sys.exit('mkreplay: ioctl scripts cannot answer control transfers; use pcap')
            ep, data, status, actual = item[1:]
            f.write('USBDEVFS_REAPURBNDELAY 0 3 %d %d 0 %d %d 0 %s\n'
                    % (ep, status, len(data), actual, data.hex().upper()))


def main():
    if len(sys.argv) < 4 or sys.argv[1] not in ('pcap', 'ioctl'):
        sys.exit(__doc__)
    env = dict(a.split('=', 1) for a in sys.argv[4:])
    dev = int(env.get('DEV', '2'))
    items = urbs(parse(sys.argv[2], env))
    (write_pcap if sys.argv[1] == 'pcap' else write_ioctl)(items, sys.argv[3], dev)


main()
