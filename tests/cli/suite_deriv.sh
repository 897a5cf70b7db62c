#!/bin/sh
# suite_deriv.sh -- the derivations (issue 16): math in $...$ in Markdown,
# equations aligned at =, each region and claim says the values it was taken
# at, certificates as substitutions, no "0 > 0" lines; the LaTeX compiles
# when pdflatex is installed (its PDF's text checked), else a skip message.
# The central difference case has the identically-zero Hurwitz minor D_2 = 0
# (p = l^2 + (w^2 - 2) l + 1, q(z) = (4 - w^2) z^2 + w^2: the z^1 row vanishes).
# Prints "ok ..." or "FAIL ..." per check.
BUILD=${BUILD:-build}
RS="$(cd "$BUILD" 2>/dev/null && pwd)/recstab"
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
ok()   { echo "ok $*"; }
fail() { echo "FAIL $*"; }
CD=cases/textbook/central-difference.case
PARK=cases/park-staggered.case

"$RS" --markdown "$CD" >"$T/cd.md" 2>"$T/err"
grep -q '0 > 0' "$T/cd.md" && fail "a '0 > 0' line in the Markdown" || ok "no '0 > 0' line"
grep -q 'identically false' "$T/cd.md" && ok "the zero condition said in words" || fail "zero condition"
grep -q '^x_{n+1} - 2\\,x_{n} + x_{n-1} + w^{2}\\,x_{n} &= 0$' "$T/cd.md" && ok "Markdown equation aligned at =" || fail "aligned equation: $(grep '&=' "$T/cd.md")"
grep -q '^\$\$p(\\lambda) = \\lambda^{2} + (w^{2} - 2)\\,\\lambda + 1\$\$$' "$T/cd.md" && ok "p in display math" || fail "p display"
grep -q '`-w' "$T/cd.md" && fail "a polynomial as code" || ok "polynomials as math, not code"
"$RS" --markdown --set muh=1 --set wh=1 "$PARK" >"$T/park.md" 2>"$T/err"
grep -q '^Taken at \$m = 1\$, \$\\mathit{muh} = 1\$, \$\\mathit{wh} = 1\$\.$' "$T/park.md" && ok "region: the values it was taken at" || fail "region values: $(grep Taken "$T/park.md")"
grep -q 'by \$m = s_{m},\\quad \\alpha = s_{\\alpha}/(1 + s_{\\alpha})\$' "$T/park.md" && ok "certificate as substitutions" || fail "certificate: $(grep ' by ' "$T/park.md")"
"$RS" --latex "$CD" >"$T/cd.tex" 2>"$T/err"
grep -q ' &= 0' "$T/cd.tex" && ok "LaTeX equations aligned at =" || fail "LaTeX align"
if command -v pdflatex >/dev/null 2>&1 && command -v pdftotext >/dev/null 2>&1; then
    (cd "$T" && pdflatex -interaction=nonstopmode cd.tex >/dev/null 2>&1)
    pdftotext "$T/cd.pdf" "$T/cd.txt" 2>/dev/null
    grep -q 'Stability region in' "$T/cd.txt" && grep -q 'Central difference' "$T/cd.txt" && ok "pdflatex: the PDF has the derivation's text" || fail "pdflatex: $(tail -5 "$T/cd.log")"
else
    echo "skip pdflatex: pdflatex/pdftotext not installed (Debian: texlive-latex-base, poppler-utils; make deps installs them)"
fi
