#!/bin/bash
# A run over two hosts: two network namespaces of the test's own, joined by a veth pair, each with
# its own address; mpirun starts the second host's daemon through a launcher that enters its
# namespace (as ssh would log in), and the processes talk over TCP only (no shared memory). The run
# writes exactly the monitors, extracts and checkpoint fields of one process.
# Needs root (ip netns); elsewhere it exits 77, which ctest reports as skipped.
# Usage: two_hosts.sh PORESPH MPIEXEC SRC WORK
set -u
poresph=$(realpath "$1") mpiexec=$2 src=$(realpath "$3") work=$4
fail() { echo "two hosts: $*" >&2; exit 1; }
a=psph_a_$$ b=psph_b_$$ net=10.77.$(($$ % 200)).
if ! ip netns add "$a" 2>/dev/null; then
  echo "two hosts: network namespaces need root here (ip netns add): not run"
  exit 77
fi
trap 'ip netns del "$a" 2>/dev/null; ip netns del "$b" 2>/dev/null' EXIT
ip netns add "$b" && ip link add "va$$" type veth peer name "vb$$" || fail "cannot make the namespaces' link"
ip link set "va$$" netns "$a" && ip link set "vb$$" netns "$b" &&
  ip -n "$a" addr add "${net}1/24" dev "va$$" && ip -n "$b" addr add "${net}2/24" dev "vb$$" &&
  ip -n "$a" link set lo up && ip -n "$b" link set lo up &&
  ip -n "$a" link set "va$$" up && ip -n "$b" link set "vb$$" up || fail "cannot address the namespaces"

rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
printf '%s slots=1\n%s slots=1\n' "${net}1" "${net}2" > hosts
# mpirun calls its launcher as ssh: [options] HOST COMMAND; this one enters HOST's namespace.
cat > enter_host.sh <<EOF
#!/bin/bash
while [[ \$1 == -* ]]; do shift; done
case \$1 in ${net}1) ns=$a ;; ${net}2) ns=$b ;; *) echo "unknown host \$1" >&2; exit 255 ;; esac
shift
exec ip netns exec \$ns /bin/sh -c "\$*"
EOF
chmod +x enter_host.sh
export OMP_NUM_THREADS=1 OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_mpi_yield_when_idle=1
launch() {
  ip netns exec "$a" "$mpiexec" --hostfile hosts -n 2 --mca plm_rsh_agent "$PWD/enter_host.sh" --mca btl tcp,self \
    --mca btl_tcp_if_include "${net}0/24" --mca oob_tcp_if_include "${net}0/24" "$@"
}

# Each process on its own host: its own address.
launch sh -c 'echo "$OMPI_COMM_WORLD_RANK $(ip -4 -o addr show scope global | awk "{print \$4}")"' | sort > where.txt
[ "$(cat where.txt)" = "$(printf '0 %s1/24\n1 %s2/24' "$net" "$net")" ] || fail "the processes' addresses: $(cat where.txt)"

sed 's/^end = 0.5/end = 0.04/' "$src/cases/poiseuille_2d.toml" > case.toml
"$poresph" run case.toml --out one --quiet > /dev/null || fail "the one-process run failed"
launch "$poresph" run case.toml --out two --quiet > two.out 2>&1 || fail "the run over two hosts failed: $(tail -5 two.out)"
cmp -s one/monitors.csv two/monitors.csv || fail "monitors.csv differs from one process's"
/usr/bin/python3 "$src/tests/compare_extracts.py" one two pvtp > /dev/null || fail "the extracts differ from one process's"
for f in one/checkpoints/*.h5; do
  /usr/bin/python3 "$src/tests/checkpoint_h5py.py" same "$f" "two/${f#one/}" || fail "checkpoint ${f#one/} differs"
done
echo "two hosts ($(tr '\n' ' ' < where.txt)): monitors, extracts and checkpoints as one process's"
