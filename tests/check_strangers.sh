#!/bin/sh
# Files from strangers (issue 20), the cases tests/bad/ cannot set up: a
# job's symbolic link out of its folder, a planted temporary-file link,
# permission bits kept, temporary files removed on a signal, FIFOs and
# huge sparse files refused before they are read, control characters
# escaped in error lines.
. tests/cli_lib.sh
ROOT=$(pwd)

fresh() { d=$(mktemp -d "$WORK/c.XXXXXX") && cd "$d"; }
have_usb() { "$QC" udev-rule 0bad:1001 >/dev/null 2>&1; } # not built with USB=0

job_link_out() {
    fresh && mkdir job out && ln -s ../out job/link &&
        echo '{"output":["link/x.pat"],"blocks":[{"region":"rect:2x2"}]}' >job/q.json &&
        expect_fail 2 "output\[0\]: 'link/x.pat' leads outside the job's folder through a symbolic link" \
            "$QC" job job/q.json && [ -z "$(ls -A out)" ] &&
        "$QC" job job/q.json --allow-outside && [ -s out/x.pat ] &&
        ln -s ../out/a.svg job/r.svg && printf '<svg/>' >out/a.svg &&
        echo '{"output":["q.pat"],"blocks":[{"region":"r.svg"}]}' >job/r.json &&
        expect_fail 2 "region: 'r.svg' leads outside" "$QC" job job/r.json
}
check job_symlinks_cannot_lead_out_of_its_folder job_link_out

job_inside_ok() {
    fresh && mkdir -p job/sub && cp "$ROOT/tests/bad/svg/bowtie.svg" job/sub/ 2>/dev/null;
    echo '{"output":["sub/q.pat"],"blocks":[{"region":"square:2"}]}' >job/q.json &&
        "$QC" job job/q.json && [ -s job/sub/q.pat ] &&
        "$QC" job job/q.json -o "$d/free.pat" && [ -s free.pat ]
}
check job_files_inside_its_folder_and_o_anywhere_still_work job_inside_ok

# The old temporary name was NAME.tmp.PID.1; exec keeps the shell's PID.
planted_temp_link() {
    fresh && sh -c 'ln -s victim out.pat.tmp.$$.1; exec "$0" generate -o out.pat' "$QC" &&
        [ ! -e victim ] && [ -f out.pat ] && [ ! -L out.pat ] &&
        [ "$(ls out.pat.tmp.* | wc -l)" -eq 1 ] # only the planted link
}
check a_planted_temp_link_is_not_followed planted_temp_link

mode_kept() {
    fresh && : >p.pat && chmod 600 p.pat && "$QC" generate -o p.pat &&
        [ "$(stat -c %a p.pat)" = 600 ] && [ -s p.pat ] &&
        (umask 027 && "$QC" generate -o n.pat) && [ "$(stat -c %a n.pat)" = 640 ]
}
check replacing_an_output_keeps_its_mode mode_kept

# The second output is a FIFO nobody reads: quiltc waits opening it, with
# the first output's temporary file made; each signal must remove it.
signal_cleans() {
    for sig in INT TERM HUP; do
        fresh && mkfifo f.svg || return 1
        # a shell without job control starts background jobs with SIGINT ignored
        env --default-signal=INT,TERM,HUP "$QC" generate -o a.pat -o f.svg &
        pid=$! n=0
        while [ "$(ls a.pat.tmp.* 2>/dev/null | wc -l)" -eq 0 ] && [ $n -lt 200 ]; do
            sleep 0.05; n=$((n + 1))
        done
        [ $n -lt 200 ] || { echo "no temp file"; kill $pid; return 1; }
        kill -s $sig $pid; wait $pid
        [ -z "$(ls -A | grep -v '^f.svg$')" ] || { echo "$sig left: $(ls -A)"; return 1; }
        cd "$WORK"
    done
}
check sigint_sigterm_sighup_remove_temp_files signal_cleans

fifo_inputs() {
    fresh && mkfifo p &&
        expect_fail 1 "'p' is not a regular file" "$QC" generate --region p &&
        mkfifo p.svg && expect_fail 1 "'p.svg' is not a regular file" "$QC" generate --family packing --motif p.svg &&
        expect_fail 1 "'p' is not a regular file" "$QC" check p &&
        expect_fail 1 "'p' is not a regular file" "$QC" job p &&
        echo '{"blocks":[{"region":"p"}]}' >j.json &&
        expect_fail 1 "'p' is not a regular file" "$QC" job j.json &&
        { ! have_usb || expect_fail 1 "'p' is not a regular file" "$QC" upload p --device 0bad:1001; }
}
check fifos_are_refused_not_waited_on fifo_inputs

sparse_refused() {
    fresh && truncate -s 2G big.pat &&
        expect_fail 1 "'big.pat' is larger than 268435456 bytes" "$QC" check big.pat &&
        expect_fail 1 "'big.pat' is larger than" "$QC" convert big.pat out.svg && [ ! -e out.svg ]
}
check a_2gb_sparse_file_is_refused_before_reading sparse_refused

escaped() {
    fresh && printf '{"blocks":[{"region":"rect:2x2","family":"\033]0;x\007\302\233y\nz"}]}' >e.json &&
        "$QC" job e.json 2>err; [ $? -eq 2 ] && [ "$(wc -l <err)" -eq 1 ] &&
        ! grep -q "$(printf '\033')" err && ! grep -q "$(printf '\007')" err &&
        ! grep -q "$(printf '\302\233')" err && grep -qF '\x1B]0;x\x07\u009By\nz' err &&
        "$QC" generate --region "$(printf 'a\033[2Jb.svg')" 2>err; [ "$(wc -l <err)" -eq 1 ] &&
        grep -qF 'a\x1B[2Jb.svg' err &&
        { ! have_usb || expect_fail 2 "bad --group 'a.nb'" "$QC" udev-rule 0bad:1001 --group "$(printf 'a\nb')"; }
}
check control_characters_are_escaped_in_errors escaped

# A 60,000-vertex motif (0.8 MB) packed once per pebble: 1.6 GB before.
packed_budget() {
    fresh && python3 -c '
import math
n = 60000
p = " ".join("%.3f,%.3f" % (50 + 40 * math.cos(6.2832 * i / n), 50 + 40 * math.sin(6.2832 * i / n)) for i in range(n))
open("m.svg", "w").write("<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 100 100\"><polygon points=\"%s\"/></svg>" % p)' &&
        expect_fail 1 "packing: about .* motif points (.* points at spacing .* mm, motif m.svg of 60001 points) exceed the limit of 4000000" \
            "$QC" generate --family packing --motif m.svg -o p.pat && [ ! -e p.pat ]
}
check packing_copies_of_a_huge_motif_are_refused packed_budget

# A fake concorde on PATH: it leaves junk beside its files and writes the
# tour FAKE_TOUR asks for ("repeat": point 0 n times; "good": 0..n-1).
fake_concorde() {
    mkdir -p bin && cat >bin/concorde <<'SH' && chmod +x bin/concorde
#!/bin/sh
pwd >>"$FAKE_LOG"
n=$(sed -n 's/^DIMENSION: //p' in.tsp)
echo junk >in.mas; echo junk >Oin.sav
{ echo "$n"; i=0; while [ $i -lt "$n" ]; do
    if [ "$FAKE_TOUR" = good ]; then echo $i; else echo 0; fi; i=$((i + 1)); done; } >out.sol
SH
}

concorde_tour_checked() {
    fresh && fake_concorde && export FAKE_LOG="$d/log" &&
        FAKE_TOUR=repeat PATH="$d/bin:$PATH" expect_fail 1 "is not a permutation of the" \
            "$QC" skeleton --path tsp --tsp concorde -o s.json && [ ! -e s.json ] &&
        FAKE_TOUR=good PATH="$d/bin:$PATH" "$QC" skeleton --path tsp --tsp concorde -o s.json &&
        [ -s s.json ] && [ "$(wc -l <log)" -eq 2 ] &&
        while read -r dir; do [ ! -e "$dir" ] || { echo "left $dir"; exit 1; }; done <log
}
check concorde_tour_must_be_a_permutation_and_its_folder_goes concorde_tour_checked

finish
