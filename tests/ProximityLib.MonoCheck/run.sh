#!/usr/bin/env bash
# The Mono smoke test (docs/unity.md): Program.cs calls every public query overload, factory and batch method and
# prints every result exactly. It runs three ways and the outputs must be identical:
#   1. on .NET 10 against the net10.0 build (the reference);
#   2. on Mono, with the library SOURCE compiled by Roslyn against Mono's own class libraries (-nostdlib, lib/mono/4.5
#      and Facades/netstandard.dll; C# 9, unsafe code as its asmdef allows, no NET define), as Unity compiles the UPM
#      package (the scene models are compiled the same way, not run);
#   3. on Mono, against the netstandard2.1 ProximityLib.dll that dotnet builds (what the NuGet package ships).
set -euo pipefail
cd "$(dirname "$0")/../.."
here=tests/ProximityLib.MonoCheck
export DOTNET_CLI_TELEMETRY_OPTOUT=1 DOTNET_NOLOGO=1

if ! command -v mono >/dev/null 2>&1; then
  apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq mono-devel >/dev/null
fi
mono_lib="$(dirname "$(readlink -f "$(command -v mono)")")/../lib/mono/4.5"
[ -f "$mono_lib/mscorlib.dll" ] && [ -f "$mono_lib/Facades/netstandard.dll" ] \
  || { echo "error: Mono's class libraries not found under $mono_lib" >&2; exit 1; }
sdk=$(dotnet --list-sdks | sed -nE 's/^(10\.[^ ]+) \[(.*)\]$/\2\/\1/p' | tail -1)
csc="$sdk/Roslyn/bincore/csc.dll"
[ -f "$csc" ] || { echo "error: Roslyn (csc.dll) not found in the .NET 10 SDK ($sdk)" >&2; exit 1; }

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
refs=()
for f in "$mono_lib"/*.dll "$mono_lib/Facades/netstandard.dll"; do refs+=("-r:$f"); done
roslyn() { dotnet "$csc" -nologo -noconfig -nostdlib -langversion:9 -nullable:enable -optimize+ -deterministic "${refs[@]}" "$@"; }
status=0

# 1. .NET 10.
dotnet build "$here/ProximityLib.MonoCheck.csproj" -c Release -v q -nologo > "$work/build.log" 2>&1 \
  || { cat "$work/build.log"; echo "error: the smoke program does not build for .NET 10" >&2; exit 1; }
dotnet "$here/bin/Release/net10.0/ProximityLib.MonoCheck.dll" > "$work/net.txt" || status=1

# 2. The library source compiled against Mono's class libraries, as Unity compiles the package.
mkdir -p "$work/mono-source"
mapfile -t sources < <(find src/ProximityLib -name '*.cs' -not -path '*/obj/*' -not -path '*/bin/*' | sort)
if ! roslyn -t:library -unsafe+ -warnaserror+ -out:"$work/mono-source/ProximityLib.dll" "${sources[@]}" > "$work/csc.log" 2>&1; then
  grep -E 'error' "$work/csc.log" | sort -u | head -20 >&2
  echo "error: the library source does not compile against Mono's class libraries" >&2
  status=1
fi
# The scene models reach Unity as source too: they must compile the same way (they are not run here).
mapfile -t scenes < <(find src/ProximityLib.Scenes -name '*.cs' -not -path '*/obj/*' -not -path '*/bin/*' | sort)
if [ -f "$work/mono-source/ProximityLib.dll" ] && ! roslyn -t:library -warnaserror+ -out:"$work/mono-source/ProximityLib.Scenes.dll" \
    -r:"$work/mono-source/ProximityLib.dll" "${scenes[@]}" > "$work/csc.log" 2>&1; then
  grep -E 'error' "$work/csc.log" | sort -u | head -20 >&2
  echo "error: the scene models do not compile against Mono's class libraries" >&2
  status=1
fi

# 3. The netstandard2.1 build (what the NuGet package ships) under Mono.
dotnet build src/ProximityLib/ProximityLib.csproj -c Release -f netstandard2.1 -v q -nologo > "$work/build.log" 2>&1 \
  || { cat "$work/build.log"; echo "error: the netstandard2.1 build failed" >&2; exit 1; }
mkdir -p "$work/mono-package"
cp src/ProximityLib/bin/Release/netstandard2.1/ProximityLib.dll "$work/mono-package/"

for run in mono-source mono-package; do
  [ -f "$work/$run/ProximityLib.dll" ] || continue
  roslyn -t:exe -out:"$work/$run/Smoke.exe" -r:"$work/$run/ProximityLib.dll" "$here/Program.cs" > "$work/csc.log" 2>&1 \
    || { cat "$work/csc.log"; echo "error: the smoke program does not compile against Mono's class libraries" >&2; exit 1; }
  mono "$work/$run/Smoke.exe" > "$work/$run.txt" || status=1
done

for run in mono-source mono-package; do
  [ -f "$work/$run.txt" ] || continue
  if ! cmp -s "$work/net.txt" "$work/$run.txt"; then
    echo "error: $run output differs from .NET 10 (first differences, < .NET 10, > Mono):" >&2
    diff "$work/net.txt" "$work/$run.txt" | head -20 >&2 || true
    status=1
  fi
done
[ "$status" = 0 ] || exit 1
echo "mono smoke ok: $(wc -l < "$work/net.txt") result lines identical on .NET 10, on Mono from source and on Mono with the netstandard2.1 build ($(mono --version | head -1 | sed -E 's/.*version ([^ ]+).*/Mono \1/'), ${SECONDS}s)"
