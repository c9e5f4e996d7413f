# Shared by the shell tests: counted checks and running `render`. Source it after setting
# RENDER (the render binary) and OUT (a folder for the outputs); end the script with `finish`.

passed=0
failed=0
pass() { passed=$((passed + 1)); echo "ok: $1"; }
fail() { failed=$((failed + 1)); echo "FAILED: $1"; }

# run NAME ARGS...: runs render, keeping the exit code in $rc, stdout and stderr in files.
run() {
    local name=$1
    shift
    "$RENDER" "$@" >"$OUT/$name.out" 2>"$OUT/$name.err"
    rc=$?
}

# expect_rc NAME WANT ARGS...: runs render and checks its exit code.
expect_rc() {
    local name=$1 want=$2
    shift 2
    run "$name" "$@"
    if [ "$rc" -eq "$want" ]; then
        pass "$name exits $want"
    else
        fail "$name exits $rc, expected $want; stderr: $(head -c 800 "$OUT/$name.err")"
    fi
}

# expect_in FILE TEXT WHAT: checks that FILE contains TEXT.
expect_in() {
    if grep -qF -- "$2" "$1"; then
        pass "$3"
    else
        fail "$3: '$2' not in $1: $(head -c 600 "$1")"
    fi
}

# check WHAT COMMAND...: passes when the command succeeds, printing its output on failure.
check() {
    local what=$1
    shift
    local output
    if output=$("$@" 2>&1); then
        pass "$what"
    else
        fail "$what: $output"
    fi
}

# finish: the summary line, and the exit code of the test.
finish() {
    echo "$passed passed, $failed failed"
    [ "$failed" -eq 0 ]
}
