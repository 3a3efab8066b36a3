#!/bin/bash
# Add the pair model of this folder (HarmonicRepulsion.H, its test
# testHarmonicRepulsion.C) to the source tree DIR as the user guide's
# "Adding a force model" says: the header into src/suspension/forces/, its
# include and its line in the registry PairModels
# (src/suspension/forces/ForceModels.H), the test into tests/suspension/.
#
#   registerModel.sh DIR
set -eu
here=$(cd "$(dirname "$0")" && pwd)
dir=${1:?usage: registerModel.sh SOURCE_TREE}
registry=$dir/src/suspension/forces/ForceModels.H
[ -f "$registry" ] || { echo "registerModel.sh: no $registry" >&2; exit 1; }

cp "$here/HarmonicRepulsion.H" "$dir/src/suspension/forces/"
cp "$here/testHarmonicRepulsion.C" "$dir/tests/suspension/"
python3 - "$registry" <<'PY'
import re, sys
path = sys.argv[1]
text = open(path).read()
include = '#include "forces/VanDerWaalsAttraction.H"\n'
# The last model of PairModels: the entry before its closing '>;'
last = re.compile(r'(using PairModels = ModelList\n<\n(?:    \w+,\n)*    \w+)\n>;')
if 'HarmonicRepulsion' in text:
    sys.exit("registerModel.sh: " + path + " registers HarmonicRepulsion already")
if include not in text or not last.search(text):
    sys.exit("registerModel.sh: " + path + " has no PairModels list to extend")
text = text.replace(include, include + '#include "forces/HarmonicRepulsion.H"\n', 1)
text = last.sub(r'\1,\n    HarmonicRepulsion\n>;', text, count=1)
open(path, 'w').write(text)
PY
