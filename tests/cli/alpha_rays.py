#!/usr/bin/env python3
"""Independent A(alpha) of the DIRK [1/3, 0; 1/4, 1/3 | 1/2, 1/2]
(cases/complex/dirk-alpha86.case), floats only, no recstab: R(z) from the
tableau by Cramer's rule, f(theta) = max over r > 0 of |R(-r e^{i theta})|
(a log-r scan, then ternary search), alpha = the largest theta with
f <= 1 by bisection.  Prints 86.46970638672578 (about 10 s), kept as a
literal in tests/cli/suite_complex.sh."""
import cmath, math
def R(z, A, b):
    a11,a12,a21,a22=A
    m11,m12,m21,m22=1-z*a11,-z*a12,-z*a21,1-z*a22
    det=m11*m22-m12*m21
    k1=(m22-m12)/det; k2=(m11-m21)/det
    return 1+z*(b[0]*k1+b[1]*k2)
def fmax(th,A,b):
    f=lambda lr: abs(R(-math.exp(lr)*cmath.exp(1j*th),A,b))
    best=max(range(-4000,4001), key=lambda i: f(i/400))
    lo,hi=(best-1)/400,(best+1)/400
    for _ in range(100):
        m1=lo+(hi-lo)/3; m2=hi-(hi-lo)/3
        if f(m1)<f(m2): lo=m1
        else: hi=m2
    return f(lo)
A=(1/3,0,1/4,1/3); b=(0.5,0.5)
lo,hi=math.radians(80),math.radians(89.9)
for _ in range(50):
    m=(lo+hi)/2
    if fmax(m,A,b)<=1: lo=m
    else: hi=m
print(math.degrees(lo))
