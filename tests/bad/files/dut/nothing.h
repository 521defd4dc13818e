/* nothing of ours */
int x = 1;
