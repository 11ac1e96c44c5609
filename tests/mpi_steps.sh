#!/bin/sh
# tests/mpi_steps.sh STEP BIN - the MPI steps of `make test` (mk/mpi.mk),
# BIN holding trk-tablegen, trk-sim and their MPI builds trk-tablegen-mpi, trk-sim-mpi.
#
#   tablegen  a q2 PDAF table, a q2 PDAFAI table (K clutter) and a K amplitude table:
#             `mpirun -np 3` with 1 and 2 OpenMP threads per rank gives the bytes of
#             the single-process trk-tablegen (1 thread)
#   sim       the same for trk-sim brekke-trackloss, brekke-errpdf, mtt (cpu_* columns aside: a CPU
#             time), clutter-null, kennedy-null and blanding-add-arl (both CSVs)
#   resume    a rank that fails: TRK_PAR_FAIL_AFTER makes rank 1 of a q2 job exit
#             halfway; a trk-sim job loses a rank to SIGKILL once its checkpoint holds
#             finished runs. Each time the job exits non-zero with a message, writes no
#             output file (nor a temporary one) and leaves the checkpoint; the run
#             resumed with the same arguments (and another thread count) takes some
#             but not all units from it, gives the bytes of the uninterrupted
#             single-process run and removes the checkpoint. A checkpoint of other
#             arguments is refused (exit status 2), and so is a damaged one.
#
# mpirun: Open MPI with --oversubscribe (3 ranks on any number of cores) and, as
# root, --allow-run-as-root; another MPI's mpirun with -np 3 only.
set -u
step=$1 bin=$2
d=$(mktemp -d) || exit 1
trap 'rm -rf "$d"' EXIT
fail() {
    echo "mpi-$step: FAILED: $*"
    exit 1
}
if mpirun --version 2>/dev/null | grep -q 'Open MPI'; then
    mpirun="mpirun --oversubscribe"
    [ "$(id -u)" = 0 ] && mpirun="$mpirun --allow-run-as-root"
else
    mpirun=mpirun
fi
np3="$mpirun -np 3"
tg=$bin/trk-tablegen sim=$bin/trk-sim
[ -x "$bin/trk-tablegen-mpi" ] && [ -x "$bin/trk-sim-mpi" ] || fail "no $bin/trk-tablegen-mpi or trk-sim-mpi"
# the CSV without the cpu_* columns (trk-sim mtt's CPU time per scan)
strip() {
    awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) keep[i] = $i !~ /^cpu_/ }
             { s = ""; for (i = 1; i <= NF; i++) if (keep[i]) s = s $i ","; print s }' "$1"
}
# same FILE_A FILE_B what
same() {
    cmp -s "$1" "$2" || fail "$3: $2 differs from the single-process $1"
}

Q2_PDAF="q2 --detector pdaf --pd 0.5:1:0.1 --lambda-vg 0.01:20:6 --samples 20000 --target-se 2e-3 --seed 3 --quiet"
Q2_AI="q2 --detector pdafai --clutter-model k --k-shape 2 --gate-gamma 36 --snr-db 10,15 --pfa 1e-3:0.1:3 \
--lambda-vg 0.01:20:6 --samples 20000 --target-se 2e-3 --seed 3 --quiet"
AMP="amp --clutter-model k --k-shape 1 --snr-db 15 --pfa 1e-3"

case $step in
tablegen)
    n=0
    for job in pdaf ai amp; do
        case $job in pdaf) args=$Q2_PDAF ;; ai) args=$Q2_AI ;; amp) args=$AMP ;; esac
        # shellcheck disable=SC2086
        OMP_NUM_THREADS=1 $tg $args --out "$d/$job.tbl" >/dev/null 2>"$d/err" || { cat "$d/err"; fail "trk-tablegen $job"; }
        for t in 1 2; do
            # shellcheck disable=SC2086
            OMP_NUM_THREADS=$t $np3 "$bin/trk-tablegen-mpi" $args --out "$d/${job}_np3_t$t.tbl" >"$d/out" 2>"$d/err" ||
                { cat "$d/err"; fail "mpirun -np 3 trk-tablegen-mpi $job ($t threads)"; }
            same "$d/$job.tbl" "$d/${job}_np3_t$t.tbl" "$job, 3 ranks x $t threads"
            n=$((n + 1))
        done
    done
    echo "mpi-tablegen: q2 PDAF, q2 PDAFAI and amplitude tables of 3 ranks x 1 and 2 threads identical to trk-tablegen ($n tables)"
    ;;
sim)
    n=0
    for job in tl ep mtt cn kn bl; do
        case $job in
        tl) args="brekke-trackloss --runs 40 --scans 60 --cell-m2 0.25 --k-shape 1 --snr-db 10 --pfa 1e-2,1e-1" ;;
        ep) args="brekke-errpdf --runs 30 --scans 60 --from 31 --pfa 1e-3,1e-1 --q2-samples 20000" ;;
        mtt) args="mtt --scans 30 --seeds 2 --clutter-count 0,50" ;;
        cn) args="clutter-null --runs 3000 --scans 30" ;;
        kn) args="kennedy-null --runs 100 --max-scans 8" ;;
        bl) args="blanding-add-arl --runs 150 --max-scans 4000" ;;
        esac
        mkdir -p "$d/ref" "$d/t1" "$d/t2"
        # shellcheck disable=SC2086
        $sim $args --seed 3 --threads 1 --quiet --no-plot --out "$d/ref/$job" >/dev/null 2>"$d/err" ||
            { cat "$d/err"; fail "trk-sim $args"; }
        for t in 1 2; do
            # shellcheck disable=SC2086
            OMP_NUM_THREADS=$t $np3 "$bin/trk-sim-mpi" $args --seed 3 --quiet --no-plot --out "$d/t$t/$job" \
                >"$d/out" 2>"$d/err" || { cat "$d/err"; fail "mpirun -np 3 trk-sim-mpi $args ($t threads)"; }
            for f in "$d/ref/$job"*.csv; do
                [ -e "$f" ] || fail "$job: no CSV"
                g=$d/t$t/${f#"$d/ref/"}
                [ -e "$g" ] || fail "$job: no $g"
                if [ "$job" = mtt ]; then
                    strip "$f" >"$d/s1" && strip "$g" >"$d/s2" || fail "cannot read $f"
                    same "$d/s1" "$d/s2" "mtt (cpu_* aside), 3 ranks x $t threads"
                else
                    same "$f" "$g" "$job, 3 ranks x $t threads"
                fi
                n=$((n + 1))
            done
        done
    done
    echo "mpi-sim: trk-sim brekke-trackloss, brekke-errpdf, mtt, clutter-null, kennedy-null, blanding-add-arl of 3 ranks x 1 and 2 threads identical to trk-sim ($n CSV files)"
    ;;
resume)
    # --- a q2 table: rank 1 exits after 40 of its work units (fault injection)
    # shellcheck disable=SC2086
    $tg $Q2_AI --threads 1 --out "$d/ai.tbl" >/dev/null 2>"$d/err" || { cat "$d/err"; fail "trk-tablegen q2"; }
    ck=$d/q2.ckpt
    # shellcheck disable=SC2086
    OMP_NUM_THREADS=1 TRK_PAR_FAIL_AFTER=40 TRK_PAR_FAIL_RANK=1 $np3 "$bin/trk-tablegen-mpi" $Q2_AI \
        --checkpoint "$ck" --checkpoint-interval 0 --out "$d/ai_mpi.tbl" >"$d/out" 2>"$d/err"
    rc=$?
    [ $rc -ne 0 ] || fail "q2: the job with a failing rank exited 0"
    grep -q 'rank 1: TRK_PAR_FAIL_AFTER=40: exits after 40 work units' "$d/err" || { cat "$d/err"; fail "q2: no message of the failing rank"; }
    ls "$d"/ai_mpi.tbl* >/dev/null 2>&1 && fail "q2: the failed job left an output file: $(ls "$d"/ai_mpi.tbl*)"
    [ -s "$ck" ] || fail "q2: no checkpoint after the failure"
    # another run's arguments: refused
    # shellcheck disable=SC2086
    $np3 "$bin/trk-tablegen-mpi" $Q2_AI --seed 4 --checkpoint "$ck" --out "$d/other.tbl" >"$d/out" 2>"$d/err5"
    rc=$?
    [ $rc -eq 2 ] && grep -q 'belongs to another run' "$d/err5" || { cat "$d/err5"; fail "q2: another run's checkpoint not refused (exit $rc)"; }
    # resumed, 2 threads per rank
    # shellcheck disable=SC2086
    OMP_NUM_THREADS=2 $np3 "$bin/trk-tablegen-mpi" $Q2_AI --checkpoint "$ck" --checkpoint-interval 0 \
        --out "$d/ai_mpi.tbl" >"$d/out" 2>"$d/err2" || { cat "$d/err2"; fail "q2: the resumed job failed"; }
    same "$d/ai.tbl" "$d/ai_mpi.tbl" "q2, resumed"
    r=$(sed -n 's/.*: \([0-9]*\) work units resumed, \([0-9]*\) computed; removed$/\1 \2/p' "$d/err2")
    set -- $r
    [ $# -eq 2 ] && [ "$1" -gt 0 ] && [ "$2" -gt 0 ] || { cat "$d/err2"; fail "q2: resumed '$r': want some units resumed, some computed"; }
    q2_res="$1 of $(($1 + $2))"
    [ -e "$ck" ] && fail "q2: the checkpoint is left after the resumed run"

    # --- a trk-sim experiment: a rank killed by SIGKILL once the checkpoint holds runs
    sargs="kennedy-null --runs 1000 --max-scans 30 --seed 3 --quiet --no-plot"
    # shellcheck disable=SC2086
    $sim $sargs --threads 2 --out "$d/kn" >/dev/null 2>"$d/err" || { cat "$d/err"; fail "trk-sim kennedy-null"; }
    ck=$d/sim.ckpt
    # shellcheck disable=SC2086
    OMP_NUM_THREADS=1 $np3 "$bin/trk-sim-mpi" $sargs --checkpoint "$ck" --checkpoint-interval 0 \
        --out "$d/kn_mpi" >"$d/out" 2>"$d/err3" &
    job=$!
    i=0
    while [ ! -s "$ck" ] && [ $i -lt 600 ] && kill -0 $job 2>/dev/null; do
        sleep 0.05
        i=$((i + 1))
    done
    [ -s "$ck" ] || { wait $job; cat "$d/err3"; fail "sim: no checkpoint within 30 s"; }
    # a rank of the job (mpirun's children are the ranks): the last one
    victim=$(pgrep -P $job | tail -1)
    if [ -z "$victim" ]; then # mpirun behind a shell
        victim=$(for p in $(pgrep -P $job); do pgrep -P "$p"; done | tail -1)
    fi
    [ -n "$victim" ] || { wait $job; fail "sim: no rank process found to kill"; }
    kill -9 "$victim"
    wait $job
    rc=$?
    [ $rc -ne 0 ] || { cat "$d/err3"; fail "sim: the job exited 0 after a rank was killed"; }
    [ -s "$d/err3" ] || fail "sim: no message after a rank was killed"
    ls "$d"/kn_mpi* >/dev/null 2>&1 && fail "sim: the killed job left output: $(ls "$d"/kn_mpi*)"
    [ -s "$ck" ] || fail "sim: no checkpoint after the kill"
    # a damaged checkpoint is refused
    cp "$ck" "$d/bad.ckpt"
    printf 'X' | dd of="$d/bad.ckpt" bs=1 seek=100 conv=notrunc 2>/dev/null
    # shellcheck disable=SC2086
    $np3 "$bin/trk-sim-mpi" $sargs --checkpoint "$d/bad.ckpt" --out "$d/bad" >"$d/out" 2>"$d/err6"
    rc=$?
    [ $rc -eq 2 ] && grep -q 'damaged' "$d/err6" || { cat "$d/err6"; fail "sim: a damaged checkpoint not refused (exit $rc)"; }
    # resumed, 2 threads per rank
    # shellcheck disable=SC2086
    OMP_NUM_THREADS=2 $np3 "$bin/trk-sim-mpi" $sargs --checkpoint "$ck" --out "$d/kn_mpi" >"$d/out" 2>"$d/err4" ||
        { cat "$d/err4"; fail "sim: the resumed job failed"; }
    same "$d/kn.csv" "$d/kn_mpi.csv" "kennedy-null, resumed"
    r=$(sed -n 's/.*: \([0-9]*\) work units resumed, \([0-9]*\) computed; removed$/\1 \2/p' "$d/err4")
    set -- $r
    [ $# -eq 2 ] && [ "$1" -gt 0 ] && [ "$2" -gt 0 ] || { cat "$d/err4"; fail "sim: resumed '$r': want some runs resumed, some computed"; }
    [ -e "$ck" ] && fail "sim: the checkpoint is left after the resumed run"
    echo "mpi-resume: a failing rank (q2) and a killed rank (trk-sim) end the job with no output; resumed ($q2_res q2 units, $1 of $(($1 + $2)) runs from the checkpoints) the bytes are the single-process ones"
    ;;
*)
    fail "unknown step (tablegen, sim, resume)"
    ;;
esac
