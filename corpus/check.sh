#!/usr/bin/env bash
# Compile-checks every shader in the stereoshift corpus with glslangValidator.
# Usage: corpus/check.sh            (from any directory)
# Exits non-zero if any shader fails; files under */include/ are includes, not shaders.
set -u

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
GLSLANG="${GLSLANG:-glslangValidator}"

pass=0
fail=0
failed=()

run() {   # run <file> <command...>
    local file="$1"; shift
    local out
    if out="$("$@" 2>&1)"; then
        return 0
    fi
    echo "FAIL: $file"
    echo "  command: $*"
    echo "$out" | sed 's/^/  /'
    return 1
}

check_one() {
    local f="$1" ok=0
    case "$f" in
        "$here"/gl330/*|"$here"/relief-tutorial/gl330/*)
            run "$f" "$GLSLANG" -G --auto-map-locations --auto-map-bindings -o /dev/null "$f" || ok=1
            run "$f" "$GLSLANG" "$f" || ok=1
            ;;
        "$here"/es300/*)
            run "$f" "$GLSLANG" "$f" || ok=1
            ;;
        "$here"/legacy-glsl/*)
            # ESSL 100 (with or without #version) and desktop 110-150: glslang's AST checks, no SPIR-V.
            run "$f" "$GLSLANG" "$f" || ok=1
            ;;
        "$here"/vk450/*|"$here"/relief-tutorial/vk450/*)
            # glslang wants -I glued to its directory (no space).
            run "$f" "$GLSLANG" -V "-I$here/vk450/include" -o /dev/null "$f" || ok=1
            ;;
        "$here"/hlsl-stage-named/*)
            # HLSL in files named by stage only (name.vert): the stage is the extension, the entry main.
            run "$f" "$GLSLANG" -D -V -S "${f##*.}" -e main -o /dev/null "$f" || ok=1
            ;;
        "$here"/hlsl/*|"$here"/relief-tutorial/hlsl/*)
            local base="${f%.hlsl}" stage entry
            stage="${base##*.}"
            if grep -Eq '(^|[^A-Za-z0-9_])main[[:space:]]*\(' "$f"; then
                entry=main
            else
                case "$stage" in
                    vert) entry=VSMain ;;
                    frag) entry=PSMain ;;
                    geom) entry=GSMain ;;
                    tesc) entry=HSMain ;;
                    tese) entry=DSMain ;;
                    comp) entry=CSMain ;;
                    *) echo "FAIL: $f (unknown stage '$stage')"; return 1 ;;
                esac
            fi
            run "$f" "$GLSLANG" -D -V -S "$stage" -e "$entry" -o /dev/null "$f" || ok=1
            ;;
        *)
            echo "FAIL: $f (not in a known dialect directory)"; ok=1
            ;;
    esac
    return $ok
}

while IFS= read -r f; do
    if check_one "$f"; then
        pass=$((pass + 1))
    else
        fail=$((fail + 1))
        failed+=("${f#"$here"/}")
    fi
done < <(find "$here/gl330" "$here/es300" "$here/legacy-glsl" "$here/vk450" "$here/hlsl" "$here/hlsl-stage-named" "$here/relief-tutorial" -type f \
            \( -name '*.vert' -o -name '*.tesc' -o -name '*.tese' -o -name '*.geom' \
               -o -name '*.frag' -o -name '*.comp' -o -name '*.hlsl' \) \
            -not -path '*/include/*' | LC_ALL=C sort)

echo "corpus check: $pass passed, $fail failed"
if [ "$fail" -ne 0 ]; then
    printf '  failed: %s\n' "${failed[@]}"
    exit 1
fi
[ "$pass" -gt 0 ] || { echo "no shaders found"; exit 1; }
exit 0
