def hard_cases(points: int = 400, seed: int = 20261123):
    return {}
