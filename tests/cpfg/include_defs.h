/* included by include.l: constants and a production */
#define LEN 2
#define BRANCH 30
B(a) --> [+(a)F(LEN)]
