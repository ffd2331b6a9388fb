#!/usr/bin/env bash
# Get the real-program corpus that data/corpus/real/MANIFEST.toml lists into a folder: each
# program from its repository at the manifest's commit and path, gzipped (gzip -9 -n) where its
# name ends .gz, its sha256 checked, and each repository's licence text (the manifest's
# licence_file) into LICENSES/OWNER+NAME.txt. The corpus is shipped in data/corpus/real
# (data/corpus/real/README.md): this script makes it again, or a copy elsewhere, from the sources;
# it only copies data files, builds nothing, and is no part of CI or make.
#
#   scripts/get_real_corpus.sh [--clones DIR] [--offline] [DEST]
#
# DEST: the corpus folder, data/corpus/real by default.
# --clones DIR: read repository OWNER/NAME from DIR/OWNER/NAME, DIR/OWNER+NAME or DIR/NAME (a
#   clone, bare or not, or a folder with one git directory inside) when it holds the commit;
#   otherwise the commit is fetched shallow from https://github.com/OWNER/NAME (the environment
#   variable REAL_CORPUS_GIT_URL replaces https://github.com, e.g. with a mirror).
# --offline: never use the network (a repository missing from DIR is an error).
# Then: DMDVOX_REAL_CORPUS=DEST python -m pytest tests/test_corpus_real.py
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

usage() {
  sed -n '9,17p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//' >&2
  exit 2
}

clones="" offline=0 dest=data/corpus/real base=${REAL_CORPUS_GIT_URL:-https://github.com}
while (($#)); do
  case "$1" in
    --clones) (($# >= 2)) || usage; clones=$2; shift 2 ;;
    --offline) offline=1; shift ;;
    -h | --help) usage ;;
    -*) echo "unknown option $1" >&2; usage ;;
    *) dest=$1; shift ;;
  esac
done
[[ -z "$clones" || -d "$clones" ]] || { echo "--clones $clones is not a folder" >&2; exit 2; }
((offline == 0)) || [[ -n "$clones" ]] || { echo "--offline needs --clones DIR" >&2; exit 2; }
mkdir -p "$dest/LICENSES"

python=python3
[[ -x .venv/bin/python ]] && python=.venv/bin/python
# One line a program: name, repository, commit, path, sha256, licence file (tab-separated: paths
# hold spaces).
listing=$("$python" - <<'EOF'
import tomllib
with open("data/corpus/real/MANIFEST.toml", "rb") as f:
    for e in tomllib.load(f)["file"]:
        print("\t".join((e["name"], e["repo"], e["commit"], e["path"], e["sha256"], e["licence_file"])))
EOF
)

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

has_commit() { # git directory or work tree, commit: never looks above the folder given
  GIT_CEILING_DIRECTORIES=$(dirname "$1") git -C "$1" cat-file -e "$2^{commit}" 2>/dev/null
}

clone_with() { # repository, commit -> a local clone holding the commit, on stdout
  local repo=$1 commit=$2 candidate inner
  if [[ -n "$clones" ]]; then
    for candidate in "$clones/$repo" "$clones/${repo/\//+}" "$clones/${repo#*/}"; do
      [[ -d "$candidate" ]] || continue
      for inner in "$candidate" "$candidate"/*/; do
        if has_commit "${inner%/}" "$commit"; then
          echo "${inner%/}"
          return
        fi
      done
    done
  fi
  ((offline == 0)) || { echo "$repo: no clone in $clones holds $commit" >&2; return 1; }
  local into="$work/${repo/\//+}@$commit"
  if [[ ! -d "$into" ]]; then
    git init -q "$into"
    git -C "$into" remote add origin "$base/$repo"
    if ! git -C "$into" fetch -q --depth 1 origin "$commit"; then
      rm -rf "$into"
      echo "$repo: cannot fetch $commit from $base/$repo" >&2
      return 1
    fi
  fi
  echo "$into"
}

got=0 failed=0
while IFS=$'\t' read -r name repo commit path sha licence; do
  target="$dest/$name"
  licence_to="$dest/LICENSES/${repo/\//+}.txt"
  if [[ -f "$target" && -f "$licence_to" ]] && [[ "$(sha256sum <"$target" | cut -d' ' -f1)" == "$sha" ]]; then
    echo "$name: already there"
    got=$((got + 1))
    continue
  fi
  if ! clone=$(clone_with "$repo" "$commit"); then
    failed=$((failed + 1))
    continue
  fi
  if ! GIT_CEILING_DIRECTORIES=$(dirname "$clone") git -C "$clone" cat-file blob "$commit:$path" >"$work/blob"; then
    echo "$name: $repo has no $path at $commit" >&2
    failed=$((failed + 1))
    continue
  fi
  if [[ "$name" == *.gz ]]; then
    gzip -9 -n -c "$work/blob" >"$work/file"
  else
    mv "$work/blob" "$work/file"
  fi
  actual=$(sha256sum <"$work/file" | cut -d' ' -f1)
  if [[ "$actual" != "$sha" ]]; then
    echo "$name: sha256 $actual, MANIFEST.toml says $sha; not written" >&2
    failed=$((failed + 1))
    continue
  fi
  cp "$work/file" "$target.part" && mv "$target.part" "$target"
  if ! GIT_CEILING_DIRECTORIES=$(dirname "$clone") git -C "$clone" cat-file blob "$commit:$licence" >"$licence_to.part"; then
    rm -f "$licence_to.part"
    echo "$name: $repo has no licence file $licence at $commit" >&2
    failed=$((failed + 1))
    continue
  fi
  mv "$licence_to.part" "$licence_to"
  echo "$name <- $repo $commit:$path"
  got=$((got + 1))
done <<<"$listing"

echo "$got programs in $dest, $failed failed"
((failed == 0))
