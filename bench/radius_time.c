/* radius_time.c -- CPU time of rs_radius_fmpz_poly alone (issue 18, third
 * step in bench/README.md), on a polynomial file written by
 * bench/radius_peers_gen.py (NAME.expr: "(c)*x^k+..." terms).
 *
 *   make all && gcc -std=c11 -D_POSIX_C_SOURCE=200809L -O2 -Iinclude \
 *       -I/usr/include/flint bench/radius_time.c build/librecstab.a \
 *       -o /tmp/rad/rt -fopenmp -lflint-arb -lflint -lgsl -lgslcblas \
 *       -ljansson -lmpfr -lgmp -lm
 *   /tmp/rad/rt NAME.expr DIGITS [REPS]      (JURY=1: also time Schur-Cohn)
 *
 * Prints the mean CPU seconds per call (CLOCK_PROCESS_CPUTIME_ID), the
 * return code, the precision used, nouter and 20-digit bounds of rho.
 * The "before" column was linked with d8e8f74's src/numeric/radius.c,
 * aberth.c and outer.c compiled separately and put ahead of the library. */
#include <stdio.h>
#include <stdlib.h>
#include <time.h>
#include "recstab/radius.h"
#include "recstab/jury.h"
static double now(void){struct timespec t;clock_gettime(CLOCK_PROCESS_CPUTIME_ID,&t);return t.tv_sec+1e-9*t.tv_nsec;}
int main(int argc,char**argv){
  fmpz_poly_t p; fmpz_t c; long k; int ch; rs_radius_t r; rs_error_t err;
  long digits=atol(argv[2]), reps=argc>3?atol(argv[3]):1, i; double t; int rc=0;
  FILE*f=fopen(argv[1],"r"); fmpz_poly_init(p); fmpz_init(c);
  /* (c)*x^k+... */
  while((ch=fgetc(f))!=EOF){ if(ch=='('){ static char buf[100000]; int n=0; while((ch=fgetc(f))!=')') buf[n++]=ch; buf[n]=0; fmpz_set_str(c,buf,10); if (fscanf(f,"*x^%ld",&k) != 1) k = 0; fmpz_poly_set_coeff_fmpz(p,k,c);} }
  rs_radius_init(r);
  t=now(); for(i=0;i<reps;i++) rc=rs_radius_fmpz_poly(r,p,digits,0,err);
  t=(now()-t)/reps;
  { char*lo=rs_radius_str_lower(r->lower,20),*hi=rs_radius_str_upper(r->upper,20);
  printf("%s d=%ld digits=%ld: %.4f s rc %d prec %ld nouter %ld  [%s, %s]\n",argv[1],(long)fmpz_poly_degree(p),digits,t,rc,(long)r->prec,(long)r->nouter,lo,hi);}
  if(getenv("JURY")){ rs_jury_t ju; rs_jury_init(ju); t=now(); rs_jury_fmpz_poly(ju,p,err); printf("  jury %.4f\n",now()-t); rs_jury_clear(ju);}
  return 0;}
