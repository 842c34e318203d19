#include <stdio.h>
#include "quiltc.h"
int main(void) { printf("quiltc %s\n", qc_version()); return 0; }
