"""The 400-step run of sdirk2 Jacobi-coupled with backward Euler
(cases/complex/sdirk2-coupled.case) from the method's definition, in double,
no recstab: g = 1 - sqrt(2)/2, the two stages solved for y' = -a y + c x
with x frozen, x' = -c y - x by backward Euler with y frozen, step h.
Used by tests/cli/suite_complex.sh."""


def run(a, c, h=1.0, steps=400):
    """|(y, x)| after steps steps from (1, 1)"""
    g = 1 - 2 ** 0.5 / 2
    y, x = 1.0, 1.0
    for _ in range(steps):
        k1 = (-a * y + c * x) / (1 + a * h * g)
        k2 = (-a * (y + h * (1 - g) * k1) + c * x) / (1 + a * h * g)
        y, x = y + h * ((1 - g) * k1 + g * k2), (x - h * c * y) / (1 + h)
    return (y * y + x * x) ** 0.5
