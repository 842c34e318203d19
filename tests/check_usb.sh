#!/bin/sh
# quiltc devices / upload / udev-rule against replayed USB devices: umockdev
# (Debian: umockdev) builds a fake sysfs and /dev/bus/usb from the device
# descriptions in tests/usb/*.umockdev, and libusb talks to them without
# hardware or root. tests/usb/mkreplay.py turns each scenario
# (tests/usb/*.urbs) into a usbmon capture (in order, bulk OUT bytes compared,
# printer class requests answered) or an ioctl script (bulk only, each URB's
# bytes compared). Each case checks the exit status and the one-line message.
# Skipped (1 Ignored) when umockdev-run is missing or quiltc was built with
# USB=0; CI installs umockdev (.ci/apt-packages.txt).
. tests/cli_lib.sh
ROOT=$(pwd)
U=$ROOT/tests/usb
SYS=/sys/devices/pci0000:00/0000:00:14.0/usb1
PY=${PYTHON:-python3}
# umockdev-run preloads its library: ASan must not insist on coming first
ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}verify_asan_link_order=0
export ASAN_OPTIONS

skip() {
    echo "tests/check_usb.sh:0:usb:IGNORE: $1"
    printf '\n-----------------------\n1 Tests 0 Failures 1 Ignored\nOK\n'
    exit 0
}
command -v umockdev-run >/dev/null 2>&1 || skip "umockdev-run not installed (apt-get install umockdev)"
command -v "$PY" >/dev/null 2>&1 || skip "$PY not installed"
[ -x "$QC" ] || skip "$QC not built"
if "$QC" upload --help 2>&1 | grep -q 'without USB support'; then
    skip "quiltc built with USB=0"
fi

# Test files: the golden 121-byte PAT, and a 13271-byte one (601 lines).
PAT=$ROOT/tests/golden/small.pat
BIG=$WORK/big.pat
awk 'BEGIN { printf "N1G00X0.000Y0.000\r\n"
             for (i = 2; i <= 600; i++)
                 printf "N%dG01X%d.%03dY%d.%03d\r\n", i, i % 37, (i * 7) % 1000, i % 23, (i * 13) % 1000
             printf "N601M02\r\n" }' >"$BIG"
BIGLEN=$(wc -c <"$BIG" | tr -d ' ')

# mock DEVICES -- CMD...: runs CMD under umockdev-run with the root hub and the
# named devices (printer, printer2, raw) and any --pcap/--ioctl options.
mock() {
    devs=""
    while [ $# -gt 0 ] && [ "$1" != "--" ]; do
        case $1 in
        --*) devs="$devs $1 $2"; shift ;;
        *) devs="$devs -d $U/$1.umockdev" ;;
        esac
        shift
    done
    shift
    # shellcheck disable=SC2086
    umockdev-run -d "$U/hub.umockdev" $devs -- "$@"
}

# replay pcap|ioctl SCENARIO OUT VAR=VALUE...
replay() {
    mode=$1 scenario=$2 out=$3
    shift 3
    "$PY" "$U/mkreplay.py" "$mode" "$U/$scenario.urbs" "$out" "$@"
}

# The stderr of CMD without umockdev's own "** Message:" lines (it reports a
# replay with no answer left, which is how transfers time out here).
run() {
    "$@" >"$WORK/.out" 2>"$WORK/.err.raw"
    rc=$?
    grep -v -e '^\*\* Message:' -e '^ *$' -e '^    [A-Z]* URB, for endpoint' "$WORK/.err.raw" >"$WORK/.err"
    return $rc
}

# ok PATTERN CMD...: exit 0, PATTERN on stdout, nothing on stderr.
ok() {
    pattern=$1
    shift
    run "$@"
    got=$?
    if [ "$got" -ne 0 ]; then echo "exit $got: $(cat "$WORK/.err")"; return 1; fi
    if [ -s "$WORK/.err" ]; then echo "stderr: $(cat "$WORK/.err")"; return 1; fi
    grep -q -- "$pattern" "$WORK/.out" || { echo "stdout lacks '$pattern': $(cat "$WORK/.out")"; return 1; }
}

# fails STATUS MESSAGE CMD...: exit STATUS, stderr exactly "quiltc: MESSAGE".
fails() {
    want=$1 msg=$2
    shift 2
    run "$@"
    got=$?
    if [ "$got" -ne "$want" ]; then echo "exit $got, wanted $want: $(cat "$WORK/.err")"; return 1; fi
    if [ "$(wc -l <"$WORK/.err")" -ne 1 ]; then echo "stderr is not one line:"; cat "$WORK/.err"; return 1; fi
    [ "$(cat "$WORK/.err")" = "quiltc: $msg" ] || { echo "stderr '$(cat "$WORK/.err")', wanted 'quiltc: $msg'"; return 1; }
}

# Until cli/main.c dispatches the USB commands there is nothing to run.
if ! grep -q cmd_upload "$ROOT/cli/main.c"; then
    skip "cli/main.c does not dispatch the USB commands yet"
fi

t_devices() {
    replay pcap printer-ok p.pcap FILE="$PAT" CHUNK=32 &&
    ok '^0bad:1001  1-2      Quilt Test Long Arm 9$' mock printer raw --pcap "$SYS/1-2=p.pcap" -- "$QC" devices &&
    grep -q '^    interface 0.0: printer class, bidirectional, bulk OUT 0x01, bulk IN 0x82, 512-byte packets$' .out &&
    grep -q '^        IEEE-1284 ID: MFG:Quilt Test;CMD:PAT;MDL:Long Arm 9;CLS:PRINTER;$' .out &&
    grep -q '^0bad:2002  1-3      Quilt Test Raw Plotter (vendor class)$' .out &&
    grep -q '^    interface 0.0: vendor class, bulk OUT 0x02, 512-byte packets$' .out &&
    ! grep -q '1d6b:0002' .out &&
    [ "$(grep -c '^0bad' .out)" -eq 2 ] &&
    ok '^1d6b:0002  1-0 ' mock printer -- "$QC" devices --all &&
    grep -q 'hub class, no bulk OUT endpoint' .out
}

t_devices_none() {
    ok '^no USB device with a bulk OUT endpoint found$' mock -- "$QC" devices &&
    [ "$(wc -l <.out)" -eq 1 ]
}

# A printer that takes a whole PAT file: the capture holds the file's bytes
# and any difference stalls the replay, so success means every byte matched.
t_printer_pat() {
    replay pcap printer-ok p.pcap FILE="$PAT" CHUNK=32 &&
    ok '^sent 121 bytes to 0bad:1001 at 1-2 (interface 0, printer, Long Arm 9)$' \
        mock printer --pcap "$SYS/1-2=p.pcap" -- "$QC" upload "$PAT" --device 0bad:1001 --chunk 32 &&
    [ "$(wc -l <.out)" -eq 1 ] &&
    replay pcap printer-ok q.pcap FILE="$BIG" CHUNK=4096 &&
    ok "^sent $BIGLEN bytes to 0bad:1001 at 1-2 (interface 0, printer, Long Arm 9)$" \
        mock printer --pcap "$SYS/1-2=q.pcap" -- "$QC" upload "$BIG" --device=1-2
}

# The same capture against a file with one byte changed: the replay never
# answers the differing transfer, so the upload fails.
t_printer_detects_wrong_bytes() {
    replay pcap printer-ok p.pcap FILE="$PAT" CHUNK=32 &&
    sed 's/N3G01/N3G00/' "$PAT" >bad.pat &&
    fails 1 "sending to 0bad:1001 at 1-2 timed out after 1 tries of 200 ms; 32 of 121 bytes delivered" \
        mock printer --pcap "$SYS/1-2=p.pcap" -- "$QC" upload bad.pat --device 0bad:1001 --chunk 32 \
        --timeout 200 --retries 0
}

t_printer_as_raw() {
    sed 's/^file 02/file 01/' "$U/raw-ok.urbs" >raw1.urbs &&
    "$PY" "$U/mkreplay.py" pcap raw1.urbs p.pcap FILE="$PAT" CHUNK=4096 &&
    ok '^sent 121 bytes to 0bad:1001 at 1-2 (interface 0, raw)$' \
        mock printer --pcap "$SYS/1-2=p.pcap" -- "$QC" upload "$PAT" --device 0bad:1001 --protocol raw
}

t_raw_bulk() {
    replay ioctl raw-ok r.ioctl FILE="$BIG" CHUNK=4096 DEV=3 &&
    ok "^sent $BIGLEN bytes to 0bad:2002 at 1-3 (interface 0, raw)$" \
        mock raw --ioctl /dev/bus/usb/001/003=r.ioctl -- "$QC" upload "$BIG" --device 1-3 &&
    sed 's/N300G01/N300G00/' "$BIG" >bad.pat || return 1
    run mock raw --ioctl /dev/bus/usb/001/003=r.ioctl -- "$QC" upload bad.pat --device 1-3
    rc=$?
    [ $rc -eq 1 ] && grep -q "; 4096 of $BIGLEN bytes delivered\$" .err ||
        { echo "exit $rc: $(cat .err)"; return 1; }
}

t_stall_then_success() {
    replay pcap printer-stall p.pcap FILE="$PAT" CHUNK=32 &&
    ok '^sent 121 bytes to 0bad:1001 at 1-2 (interface 0, printer, Long Arm 9)$' \
        mock printer --pcap "$SYS/1-2=p.pcap" -- "$QC" upload "$PAT" --device 0bad:1001 --chunk 32
}

t_stall_paper_empty() {
    replay pcap printer-stall-paper p.pcap FILE="$PAT" CHUNK=32 &&
    fails 1 "0bad:1001 at 1-2 stalled: printer reports paper empty; 32 of 121 bytes delivered" \
        mock printer --pcap "$SYS/1-2=p.pcap" -- "$QC" upload "$PAT" --device 0bad:1001 --chunk 32
}

t_offline_before_sending() {
    replay pcap printer-offline p.pcap FILE="$PAT" &&
    fails 1 "printer 0bad:1001 at 1-2 reports offline, error; nothing sent" \
        mock printer --pcap "$SYS/1-2=p.pcap" -- "$QC" upload "$PAT" --device 0bad:1001
}

t_stall_every_time() {
    replay ioctl raw-stall r.ioctl FILE="$BIG" CHUNK=4096 DEV=3 &&
    fails 1 "endpoint 0x02 of 0bad:2002 at 1-3 stalled on 3 tries; 0 of $BIGLEN bytes delivered" \
        mock raw --ioctl /dev/bus/usb/001/003=r.ioctl -- "$QC" upload "$BIG" --device 0bad:2002 --retries 2
}

t_timeouts() {
    replay pcap printer-hang p.pcap FILE="$PAT" CHUNK=32 &&
    fails 1 "sending to 0bad:1001 at 1-2 timed out after 3 tries of 100 ms; 32 of 121 bytes delivered" \
        mock printer --pcap "$SYS/1-2=p.pcap" -- "$QC" upload "$PAT" --device 0bad:1001 --chunk 32 \
        --timeout 100 --retries 2
}

t_unplugged_halfway() {
    replay ioctl raw-unplug r.ioctl FILE="$BIG" CHUNK=4096 DEV=3 &&
    fails 1 "USB device 0bad:2002 at 1-3 was unplugged; 5096 of $BIGLEN bytes delivered" \
        mock raw --ioctl /dev/bus/usb/001/003=r.ioctl -- "$QC" upload "$BIG" --device 0bad:2002
}

t_no_device() {
    fails 1 "no USB device matches '0bad:9999' (see quiltc devices)" \
        mock printer raw -- "$QC" upload "$PAT" --device 0bad:9999 &&
    fails 1 "no USB device matches '1-7' (see quiltc devices)" \
        mock printer raw -- "$QC" upload "$PAT" --device 1-7 &&
    fails 1 "no USB device matches '0bad:1001' (see quiltc devices)" \
        mock -- "$QC" upload "$PAT" --device 0bad:1001
}

t_two_devices() {
    fails 1 "2 USB devices match '0bad:1001': 0bad:1001 at 1-2, 0bad:1001 at 1-4; choose one with --device BUS-PORT" \
        mock printer2 printer -- "$QC" upload "$PAT" --device 0bad:1001 &&
    replay pcap printer-ok p.pcap FILE="$PAT" CHUNK=4096 DEV=4 &&
    ok '^sent 121 bytes to 0bad:1001 at 1-4 (interface 0, printer, Long Arm 9)$' \
        mock printer printer2 --pcap "$SYS/1-4=p.pcap" -- "$QC" upload "$PAT" --device 1-4
}

t_no_bulk_out() {
    fails 1 "interface 1 of USB device 0bad:1001 at 1-2 has no bulk OUT endpoint (see quiltc devices)" \
        mock printer -- "$QC" upload "$PAT" --device 0bad:1001 --interface 1 &&
    fails 1 "USB device 1d6b:0002 at 1-0 has no bulk OUT endpoint to send a pattern to" \
        mock printer -- "$QC" upload "$PAT" --device 1d6b:0002
}

# The device node unreadable: as root, drop the capabilities that bypass
# file permissions so open() fails with EACCES as it would for a user.
t_access_denied() {
    if [ "$(id -u)" -eq 0 ]; then
        drop="setpriv --inh-caps=-dac_override,-dac_read_search --bounding-set=-dac_override,-dac_read_search"
        command -v setpriv >/dev/null 2>&1 || { echo "setpriv missing (util-linux)"; return 1; }
    else
        drop=""
    fi
    fails 1 "permission denied opening USB device 0bad:1001 at 1-2 (run 'quiltc udev-rule 0bad:1001' for a rule that allows it)" \
        mock printer -- sh -c 'chmod 000 "$UMOCKDEV_DIR/dev/bus/usb/001/002" && exec '"$drop"' "$@"' sh \
        "$QC" upload "$PAT" --device 0bad:1001 &&
    ok 'IEEE-1284 ID: no permission to open the device (see quiltc udev-rule 0bad:1001)$' \
        mock printer -- sh -c 'chmod 000 "$UMOCKDEV_DIR/dev/bus/usb/001/002" && exec '"$drop"' "$@"' sh \
        "$QC" devices
}

# Ctrl-C while a transfer waits: the first chunk went through, the second
# gets no answer; SIGINT cancels it and quiltc says how far it got.
t_ctrl_c() {
    replay pcap printer-hang p.pcap FILE="$PAT" CHUNK=32 &&
    mock printer --pcap "$SYS/1-2=p.pcap" -- sh -c 'echo $$ >pid; exec "$@"' sh \
        "$QC" upload "$PAT" --device 0bad:1001 --chunk 32 --timeout 60000 >.out 2>.err.raw &
    mpid=$!
    i=0
    while [ ! -s pid ] && [ $i -lt 100 ]; do sleep 0.1; i=$((i + 1)); done
    sleep 2
    kill -INT "$(cat pid)"
    wait $mpid
    rc=$?
    grep -v -e '^\*\* Message:' -e '^ *$' -e '^    [A-Z]* URB, for endpoint' .err.raw >.err
    [ $rc -eq 1 ] || { echo "exit $rc: $(cat .err)"; return 1; }
    [ "$(cat .err)" = "quiltc: interrupted; 32 of 121 bytes delivered to 0bad:1001 at 1-2" ] ||
        { echo "stderr: $(cat .err)"; return 1; }
}

# A progress bar only on a terminal (script(1) gives one), none with --quiet.
t_progress_bar() {
    command -v script >/dev/null 2>&1 || { echo "script (util-linux) missing"; return 1; }
    replay pcap printer-ok p.pcap FILE="$PAT" CHUNK=32 &&
    mock printer --pcap "$SYS/1-2=p.pcap" -- script -qec \
        "'$QC' upload '$PAT' --device 0bad:1001 --chunk 32" /dev/null >tty.out 2>&1 &&
    grep -q '\[##############################\] 100%  121/121 bytes' tty.out &&
    grep -q 'sent 121 bytes' tty.out &&
    mock printer --pcap "$SYS/1-2=p.pcap" -- script -qec \
        "'$QC' upload '$PAT' --device 0bad:1001 --chunk 32 --quiet" /dev/null >tty.out 2>&1 &&
    ! grep -q -e '100%' -e 'sent' tty.out
}

t_quiet() {
    replay pcap printer-ok p.pcap FILE="$PAT" CHUNK=32 &&
    run mock printer --pcap "$SYS/1-2=p.pcap" -- "$QC" upload "$PAT" --device 0bad:1001 --chunk 32 -q &&
    [ ! -s .out ] && [ ! -s .err ]
}

t_usage() {
    fails 2 "bad --device 'usb1' (want VID:PID in hex, e.g. 0bad:1001, or BUS-PORT, e.g. 1-2.3)" \
        "$QC" upload "$PAT" --device usb1 &&
    fails 2 "bad --device '0bad:10011' (want VID:PID in hex, e.g. 0bad:1001, or BUS-PORT, e.g. 1-2.3)" \
        "$QC" upload "$PAT" --device 0bad:10011 &&
    fails 2 "upload: no --device given (see quiltc devices)" "$QC" upload "$PAT" &&
    fails 2 "upload: --chunk must be a whole number from 1 to 1048576, not '0'" \
        "$QC" upload "$PAT" --device 1-2 --chunk 0 &&
    fails 2 "upload: --protocol must be printer or raw, not 'hpgl'" \
        "$QC" upload "$PAT" --device 1-2 --protocol hpgl &&
    fails 2 "upload: --timeout needs a value" "$QC" upload "$PAT" --device 1-2 --timeout &&
    fails 2 "upload: unknown option '--speed' (try quiltc upload --help)" \
        "$QC" upload "$PAT" --device 1-2 --speed 3 &&
    fails 1 "cannot open 'missing.pat': No such file or directory" \
        "$QC" upload missing.pat --device 1-2 &&
    : >empty.pat &&
    fails 1 "'empty.pat' is empty: nothing to send" "$QC" upload empty.pat --device 1-2
}

t_udev_rule() {
    ok '^SUBSYSTEM=="usb", ENV{DEVTYPE}=="usb_device", ATTR{idVendor}=="0bad", ATTR{idProduct}=="1001", MODE="0660", GROUP="plugdev", TAG+="uaccess"$' \
        "$QC" udev-rule 0BAD:1001 &&
    [ "$(grep -vc '^#' .out)" -eq 1 ] &&
    ok 'GROUP="dialout"' "$QC" udev-rule 0bad:1001 --group dialout &&
    fails 2 "udev-rule: want the device's VID:PID in hex, e.g. quiltc udev-rule 0bad:1001 (see quiltc devices)" \
        "$QC" udev-rule 1-2 &&
    fails 2 "udev-rule: bad --group 'a\"b' (letters, digits, '_' and '-')" \
        "$QC" udev-rule 0bad:1001 --group 'a"b'
}

# The kernel-driver and busy cases through tests/usb/libusb_shim.c (what
# umockdev cannot replay), preloaded after umockdev's own library.
shim() {
    cc -shared -fPIC -o "$WORK/shim.so" "$U/libusb_shim.c" $(pkg-config --cflags libusb-1.0) -ldl
}

t_interface_busy() {
    shim || return 1
    fails 1 "interface 0 of 0bad:1001 at 1-2 is busy: another program or driver holds it" \
        mock printer -- sh -c "$(cat <<'SH'
QC_SHIM=busy LD_PRELOAD="$LD_PRELOAD:$0/shim.so" exec "$@"
SH
)" "$WORK" "$QC" upload "$PAT" --device 0bad:1001
}

t_kernel_driver_detached_and_restored() {
    shim && rm -f shim.log && replay pcap printer-ok p.pcap FILE="$PAT" CHUNK=32 || return 1
    ok '^sent 121 bytes to 0bad:1001 at 1-2 (interface 0, printer, Long Arm 9)$' \
        mock printer --pcap "$SYS/1-2=p.pcap" -- sh -c "$(cat <<'SH'
QC_SHIM=driver QC_SHIM_LOG=$0/shim.log LD_PRELOAD="$LD_PRELOAD:$0/shim.so" exec "$@"
SH
)" "$WORK" "$QC" upload "$PAT" --device 0bad:1001 --chunk 32 || return 1
    [ "$(cat "$WORK/shim.log")" = "$(printf 'detach 0\nattach 0')" ] ||
        { echo "driver calls: $(cat "$WORK/shim.log")"; return 1; }
    rm -f "$WORK/shim.log"
    fails 1 "interface 0 of 0bad:1001 at 1-2 is busy: another program or driver holds it" \
        mock printer -- sh -c "$(cat <<'SH'
QC_SHIM=stuck QC_SHIM_LOG=$0/shim.log LD_PRELOAD="$LD_PRELOAD:$0/shim.so" exec "$@"
SH
)" "$WORK" "$QC" upload "$PAT" --device 0bad:1001 || return 1
    [ "$(cat "$WORK/shim.log")" = "detach 0" ] || { echo "driver calls: $(cat "$WORK/shim.log")"; return 1; }
}

check devices_lists_printer_and_raw t_devices
check devices_none t_devices_none
check printer_takes_whole_pat t_printer_pat
check printer_replay_detects_wrong_bytes t_printer_detects_wrong_bytes
check printer_interface_as_raw t_printer_as_raw
check raw_bulk_device t_raw_bulk
check stall_then_success t_stall_then_success
check stall_paper_empty t_stall_paper_empty
check offline_before_sending t_offline_before_sending
check stall_every_time t_stall_every_time
check repeated_timeouts t_timeouts
check unplugged_halfway t_unplugged_halfway
check no_device t_no_device
check two_matching_devices t_two_devices
check no_bulk_out_endpoint t_no_bulk_out
check access_denied t_access_denied
check interface_busy t_interface_busy
check kernel_driver_detached_and_restored t_kernel_driver_detached_and_restored
check ctrl_c t_ctrl_c
check progress_bar_on_tty t_progress_bar
check quiet t_quiet
check usage_errors t_usage
check udev_rule t_udev_rule
finish
