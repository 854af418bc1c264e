#include "/etc/passwd"
// error: 1:10 refused: the include file "/etc/passwd" is outside the allowed folders (the scene's folder, --include-path folders, POV-Ray's include folder)
