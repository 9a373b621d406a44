#!/usr/bin/env bash
# The guard for the unity build (the demo preset compiles each library's
# sources in batches, several .cpp files in one translation unit): a name
# declared in one file's anonymous namespace (or `static` at namespace
# scope) must not be declared so in another file of the same library, or
# the batch that holds both stops compiling. CI builds file by file (its
# compiler cache then serves every clone), so without this check a new file
# repeating a helper's name (`vec`, `kPi`, `cross2`, ...) would break the
# demo unseen.
#
# Reads which library each source belongs to from a configured build folder
# (default build/release) and the names from universal-ctags. Identical
# type aliases (`using json = nlohmann::json;`) may repeat and are skipped.
# Exit 1, with each repeated name and where, when one is found.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build/release}
if [ ! -f "$build/build.ninja" ]; then
  echo "check-unity-names: $build/build.ninja not found: configure the build first" >&2
  exit 2
fi
if ! ctags --version 2>/dev/null | grep -q "Universal Ctags"; then
  echo "check-unity-names: universal-ctags is missing (tools/setup.sh installs it)" >&2
  exit 2
fi

# target <TAB> source, for the project's libraries and programs (not the
# tests and benchmarks, which compile file by file).
pairs=$(sed -n -E 's#^build ([^ ]*/)?CMakeFiles/([A-Za-z0-9_]+)\.dir/[^ ]*\.o: CXX_COMPILER[^ ]* ([^ ]+\.cpp)( .*)?$#\2\t\3#p' \
  "$build/build.ninja" | grep -v -E $'\t'"$PWD/(tests|tools)/" || true)
if [ -z "$pairs" ]; then
  echo "check-unity-names: no sources found in $build/build.ninja" >&2
  exit 2
fi

status=0
for target in $(cut -f1 <<<"$pairs" | sort -u); do
  mapfile -t sources < <(awk -F'\t' -v t="$target" '$1 == t { print $2 }' <<<"$pairs")
  [ ${#sources[@]} -gt 1 ] || continue
  ctags --output-format=u-ctags --fields=nKZs --fields-C++=+{properties} --c++-kinds=+p-lmeD \
    --extras=-q -f - "${sources[@]}" 2>/dev/null |
    awk -F'\t' -v root="$PWD/" -v target="$target" '
      /^!_/ { next }
      {
        name = $1; file = $2; sub(root, "", file)
        kind = ""; line = ""; scope = ""; props = ""
        for (i = 4; i <= NF; ++i) {
          if ($i ~ /^line:/) line = substr($i, 6)
          else if ($i ~ /^scope:namespace:/) scope = substr($i, 17)
          else if ($i ~ /^scope:/) scope = "-"
          else if ($i ~ /^properties:/) props = $i
          else if ($i !~ /:/) kind = $i
        }
        if (name ~ /^__anon/ || scope == "-") next
        if (kind !~ /^(function|variable|struct|class|union|enum|typedef|prototype)$/) next
        anon = (scope ~ /(^|::)__anon[0-9a-f]+$/)
        stat = (props ~ /static/ && kind ~ /^(function|variable)$/)
        if (!anon && !stat) next
        pattern = $3
        if (kind == "typedef") {
          # an identical alias may repeat; a different one with the same name may not
          if ((name, "pattern") in seen && seen[name, "pattern"] == pattern) next
          seen[name, "pattern"] = pattern
        }
        if (!((name, file) in where)) {
          where[name, file] = 1
          files[name] = files[name] " " file ":" line
          count[name]++
        }
      }
      END {
        bad = 0
        for (n in count)
          if (count[n] > 1) {
            printf "check-unity-names: %s: \"%s\" is declared in more than one file'"'"'s anonymous namespace (or static):%s\n", target, n, files[n]
            bad = 1
          }
        exit bad
      }' || status=1
done
if [ $status -ne 0 ]; then
  echo "check-unity-names: rename one of each (the demo preset compiles these files in one unity batch)" >&2
  exit 1
fi
echo "check-unity-names: no name repeats in a library's anonymous namespaces"
