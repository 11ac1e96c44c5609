#!/bin/sh
# params_doc.sh BIN - docs/parameters.md against the code, a step of make test
# (mk/params-doc.mk):
#   - every tracker key that `trk-lcm-bridge --print-config` prints (the
#     defaults of trk_tracker_default_params, and the tools' defaults of the
#     unselected methods) has a row in the page with that default, word for
#     word, and every key of the page is printed (sensor keys: N = 0);
#   - every field name the check reports (the string literals of
#     src/tracker_params.c, sensor[N].<member> for the sensors) is named in
#     the page's "refused as" column, and every name there is one the check
#     can report;
#   - every parameter field the shared library describes (src/shared/layout.c,
#     whose units and ranges the Python binding shows) is a row of the page.
set -u
bin=$1
STEP=params-doc
. tests/step_lib.sh
doc=docs/parameters.md
[ -f "$doc" ] || fail "no $doc"
"$bin/trk-lcm-bridge" --print-config > "$T/config" 2> "$T/err" || fail "trk-lcm-bridge --print-config: $(cat "$T/err")"
# the tracker's keys and their printed defaults (sensor 0 only)
sed -n '/^# tracker configuration/,$p' "$T/config" | grep -v '^#' | grep -v '^sensor\.[1-9]' |
    sed 's/^sensor\.0\./sensor.N./' | awk -F' = ' 'NF == 2 { print $1 "\t" $2 }' | sort > "$T/code"
[ -s "$T/code" ] || fail "no tracker key in the output of --print-config"
# the page's rows: | `key` | field | meaning | unit | `default` | valid | refused as |
awk -F' [|] ' '/^[|] `/ {
    k = $1; sub(/^[|] `/, "", k); sub(/`$/, "", k)
    d = $5; gsub(/`/, "", d)
    print k "\t" d }' "$doc" | sort > "$T/doc"
[ -s "$T/doc" ] || fail "no parameter row in $doc"
bad=0
while IFS="$(printf '\t')" read -r k v; do
    d=$(awk -F'\t' -v k="$k" '$1 == k { print $2 }' "$T/doc")
    if [ -z "$d" ]; then echo "$STEP: $k (default $v) has no row in $doc"; bad=$((bad + 1))
    elif [ "$d" != "$v" ]; then echo "$STEP: $k: $doc says default $d, the code $v"; bad=$((bad + 1)); fi
done < "$T/code"
cut -f1 "$T/code" > "$T/code_keys"
for k in $(cut -f1 "$T/doc"); do
    grep -qxF "$k" "$T/code_keys" || { echo "$STEP: $doc has a row for $k, which the tools do not print"; bad=$((bad + 1)); }
done
[ $bad = 0 ] || fail "$bad differences between $doc and the defaults"
ok "$(wc -l < "$T/code") keys: every default as documented"
# field names: the check's literals against the page's last column
grep -o '"[a-z_][a-z0-9_.]*"' src/tracker_params.c | tr -d '"' |
    grep -vxE 'tracker_internal.h|clutter_density' | sort -u > "$T/fields"
grep -o '"\][.][a-z0-9_]*"' src/tracker_params.c | sed 's/^"\]/sensor[N]/; s/"$//' | sort -u >> "$T/fields"
sort -u -o "$T/fields" "$T/fields"
awk -F' [|] ' '/^[|] `/ { print $7 }' "$doc" | grep -o '`[^`]*`' | tr -d '`' | sort -u > "$T/doc_fields"
grep -o '`[a-z_][a-z0-9_.]*`' "$doc" | tr -d '`' | sort -u > "$T/doc_words"
for f in $(cat "$T/fields"); do
    grep -qxF "$f" "$T/doc_fields" || grep -qxF "$f" "$T/doc_words" ||
        { echo "$STEP: the check reports $f, which $doc does not name"; bad=$((bad + 1)); }
done
for f in $(cat "$T/doc_fields"); do
    grep -qxF "$f" "$T/fields" || { echo "$STEP: $doc names $f as refused, which the check never reports"; bad=$((bad + 1)); }
done
[ $bad = 0 ] || fail "$bad differences between $doc and the check's field names"
ok "$(wc -l < "$T/fields") field names of the check, each named in $doc"
# the fields the shared library describes (src/shared/layout.c: the names, units
# and ranges the Python binding's parameters carry) against the page's C fields
awk -F' [|] ' '/^[|] `/ { print $2 }' "$doc" | grep -o '`[^`]*`' | tr -d '`' | sort -u > "$T/doc_cfields"
{ sed -n '/^static const struct layout_row params_rows/,/^};/p' src/shared/layout.c | grep -v "'s'" |
      grep -oE '(REAL|ENUM|ROW)\(P, [a-z_.0-9]+' | sed 's/^.*(P, //'
  sed -n '/^static const struct layout_row sensor_rows/,/^};/p' src/shared/layout.c |
      grep -oE '(REAL|ENUM|ROW)\(S, [a-z_.0-9]+' | sed 's/^.*(S, /sensor[N]./'; } | sort -u > "$T/layout_fields"
[ -s "$T/layout_fields" ] || fail "no parameter row in src/shared/layout.c"
for f in $(cat "$T/layout_fields"); do
    grep -qxF "$f" "$T/doc_cfields" || { echo "$STEP: the shared library describes $f, which $doc does not list"; bad=$((bad + 1)); }
done
[ $bad = 0 ] || fail "$bad fields of src/shared/layout.c missing from $doc"
ok "$(wc -l < "$T/layout_fields") fields the Python binding reads from the shared library, each a row of $doc"
